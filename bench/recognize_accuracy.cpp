// Single-stroke accuracy on labelled real drawings (recognize_accuracy.hpp).
//
// Shapes: $1 circle, rectangle, triangle; gestures circle, square, line. Non-shapes (must stay
// freeform): $1 pigtail, question mark, braces, delete mark; gestures letters S and R, P,
// question mark, sol key, spiral, half note, stick figure, pitchfork, null, asterisk. Only
// drawings of one stroke count here (several strokes: group_recognize_bench). Neither: stars,
// carets, arrows, a one-stroke D (a closed outline of an arc and a segment), the exclamation
// point's bar (its dot was dropped), the polyline letters (N, M, ...) and the touch swipes
// (left, right, up, down: flicks, not drawn lines).
//
// The tolerance derivation: every stroke is recognized at epsilon = g * size for g on a grid;
// on the writers used for tuning, f_max is the largest g whose non-shape snaps, plus one standard
// error over the writers, stay <= 1.5% in every corpus, and f the smallest g that names shapes
// within 1 point of f_max's rate (the room between them is the pen's). Leave-one-subject-out:
// each writer is scored with the (f, f_max) derived without them.
#include "recognize_accuracy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

namespace penshape::bench {
namespace {

const std::map<std::string, std::set<std::string>> kShapes{
    {"circle", {"circle", "ellipse"}},
    {"rectangle", {"rectangle", "square", "quadrilateral"}},
    {"square", {"rectangle", "square", "quadrilateral"}},
    {"triangle", {"triangle"}},
    {"line", {"segment"}},
};
// clang-format off
const std::set<std::string> kNonShapes{
    "pigtail", "question_mark", "left_curly_brace", "right_curly_brace", "delete_mark",
    "letter_S", "letter_R", "P", "sol_key", "spiral", "half_note", "stick_figure",
    "pitchfork", "null", "asterisk"};
// clang-format on

constexpr double kFalseSnapLimit = 0.015; // the default-run target
constexpr double kShapeRateSlack = 0.01;  // f: within 1 point of f_max's shape rate
constexpr int kGridSteps = 13;            // g = 0.09, 0.095, ..., 0.15
double grid_fraction(int k) { return 0.09 + 0.005 * k; }

struct Tally {
  int shapes = 0, shapes_right = 0, non_shapes = 0, snapped = 0;
  void add(const Sample& s, ShapeClass c) {
    if (s.targets != nullptr) {
      ++shapes;
      shapes_right += s.targets->contains(to_string(c)) ? 1 : 0;
    } else {
      ++non_shapes;
      snapped += c != ShapeClass::kFreeform && c != ShapeClass::kDot ? 1 : 0;
    }
  }
  void add(const Tally& t) {
    shapes += t.shapes, shapes_right += t.shapes_right;
    non_shapes += t.non_shapes, snapped += t.snapped;
  }
  [[nodiscard]] double right() const { return shapes ? 1.0 * shapes_right / shapes : 1.0; }
  [[nodiscard]] double false_snaps() const { return non_shapes ? 1.0 * snapped / non_shapes : 0.0; }
  [[nodiscard]] std::string text() const {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%5.1f%% / %4.1f%%", 100 * right(), 100 * false_snaps());
    return buf;
  }
};

struct Rule {
  double f = 0.0;
  double f_max = 0.0;
};

ShapeClass classify(const std::vector<StrokePoint>& points, const RecognizerConfig& config) {
  try {
    return recognize(points, config).shape;
  } catch (const InvalidInput&) {
    return ShapeClass::kFreeform; // cannot happen on these corpora; counted as not snapped
  }
}

RecognizerConfig config_of(const Rule& rule, double pen_radius) {
  RecognizerConfig c;
  c.tolerance_size_fraction = rule.f;
  c.max_tolerance_fraction = rule.f_max;
  c.pen_radius = pen_radius;
  return c;
}

// The stroke moved to the origin and scaled so that its bounding-box diagonal is `size`.
std::vector<StrokePoint> rescaled(const std::vector<StrokePoint>& in, double size) {
  double xlo = in[0].x, xhi = xlo, ylo = in[0].y, yhi = ylo;
  for (const StrokePoint& p : in) {
    xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
    ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
  }
  const double diagonal = std::hypot(xhi - xlo, yhi - ylo);
  const double s = diagonal > 0 ? size / diagonal : 1.0;
  std::vector<StrokePoint> out = in;
  for (StrokePoint& p : out) p = {(p.x - xlo) * s, (p.y - ylo) * s, p.t};
  return out;
}

// tallies[subject][k]: the subject's counts at epsilon = grid_fraction(k) * size.
using SubjectSweep = std::map<std::string, std::vector<Tally>>;

SubjectSweep sweep(const std::vector<Sample>& samples) {
  SubjectSweep out;
  for (const Sample& s : samples) {
    std::vector<Tally>& row = out[s.drawing->subject];
    row.resize(kGridSteps);
    const std::vector<StrokePoint>& points = s.drawing->strokes.front();
    const double size = choose_tolerance(points, {}).size;
    for (int k = 0; k < kGridSteps; ++k) {
      RecognizerConfig c;
      c.tolerance = grid_fraction(k) * size;
      if (!(c.tolerance > 0)) c.tolerance = 1.0; // a dot: any tolerance
      row[static_cast<std::size_t>(k)].add(s, classify(points, c));
    }
  }
  return out;
}

// The corpus's non-shape snap rate at grid step k plus one standard error over its writers
// (`left_out` excepted). The limit is meant for writers the rule never saw: a tolerance that keeps
// the sample's rate just under it fails on the next writer who snaps a little more (each fold of
// the leave-one-subject-out run picked the largest such g and its held-out writer paid for it).
// The writer, not the drawing, is the unit that varies, so the error is the ratio estimate's over
// writers, sum_w (s_w - p n_w)^2 / N^2 * W / (W - 1): the one-standard-error rule.
double false_snap_bound(const SubjectSweep& sw, const std::string& corpus,
                        const std::string& left_out, int k) {
  std::vector<const Tally*> writers;
  Tally pooled;
  for (const auto& [subject, row] : sw) {
    if (subject == left_out || subject.substr(0, subject.find('/')) != corpus) continue;
    const Tally& t = row[static_cast<std::size_t>(k)];
    if (t.non_shapes == 0) continue;
    writers.push_back(&t);
    pooled.add(t);
  }
  if (writers.size() < 2) return pooled.false_snaps();
  const double p = pooled.false_snaps();
  double sum = 0.0;
  for (const Tally* t : writers) sum += std::pow(t->snapped - p * t->non_shapes, 2);
  const double w = static_cast<double>(writers.size());
  const double n = pooled.non_shapes;
  return p + std::sqrt(sum * w / (w - 1)) / n;
}

// The rule derived from every subject's sweep except `left_out` (empty: all subjects). f_max
// holds the false-snap limit in every corpus (subjects are "corpus/writer"), not only pooled:
// the limit is each default run's, and one corpus must not pay for another's clean non-shapes.
Rule derive(const SubjectSweep& sw, const std::string& left_out) {
  std::vector<Tally> total(kGridSteps);
  std::map<std::string, std::vector<Tally>> by_corpus;
  for (const auto& [subject, row] : sw) {
    if (subject == left_out) continue;
    std::vector<Tally>& corpus = by_corpus[subject.substr(0, subject.find('/'))];
    corpus.resize(kGridSteps);
    for (std::size_t k = 0; k < row.size(); ++k) total[k].add(row[k]), corpus[k].add(row[k]);
  }
  int top = 0;
  for (int k = 0; k < kGridSteps; ++k) {
    bool within = true;
    for (const auto& [corpus, row] : by_corpus) {
      within = within && false_snap_bound(sw, corpus, left_out, k) <= kFalseSnapLimit;
    }
    if (within) top = k;
  }
  int low = top;
  const double best = total[static_cast<std::size_t>(top)].right();
  while (low > 0 && total[static_cast<std::size_t>(low - 1)].right() >= best - kShapeRateSlack) {
    --low;
  }
  return {grid_fraction(low), grid_fraction(top)};
}

void print_sweep(const SubjectSweep& sw) {
  std::vector<Tally> total(kGridSteps);
  for (const auto& [subject, row] : sw) {
    for (std::size_t k = 0; k < row.size(); ++k) total[k].add(row[k]);
  }
  std::printf("  epsilon / size   shapes right / non-shapes snapped (all subjects)\n");
  for (int k = 0; k < kGridSteps; ++k) {
    std::printf("  %.3f           %s\n", grid_fraction(k),
                total[static_cast<std::size_t>(k)].text().c_str());
  }
}

} // namespace

const std::set<std::string>* shape_targets(const std::string& label) {
  const auto it = kShapes.find(label);
  return it == kShapes.end() ? nullptr : &it->second;
}

bool is_non_shape(const std::string& label) { return kNonShapes.contains(label); }

std::vector<Sample> single_stroke_samples(const std::vector<Drawing>& drawings) {
  std::vector<Sample> out;
  for (const Drawing& d : drawings) {
    if (d.strokes.size() != 1) continue;
    if (const std::set<std::string>* targets = shape_targets(d.label)) {
      out.push_back({&d, targets});
    } else if (is_non_shape(d.label)) {
      out.push_back({&d, nullptr});
    }
  }
  return out;
}

namespace {

constexpr double kSizesMm[] = {15, 40, 80, 150};
constexpr double kRadiiMm[] = {0.25, 0.5, 1, 2};
constexpr std::size_t kCells = 4;

// The rule before issue 23, as the baseline: min(5 R, 12.5% of the size).
RecognizerConfig former_config(double pen_radius) {
  RecognizerConfig c;
  c.tolerance_size_fraction = 1e-12;
  c.tolerance_pen_radii = 5.0;
  c.max_tolerance_fraction = 0.125;
  c.pen_radius = pen_radius;
  return c;
}

using Table = std::array<std::array<Tally, kCells>, kCells>;

struct Evaluation {
  Tally shipped, all, loso, former;
  std::map<std::string, Tally> per_label; // leave-one-subject-out
  Table table_shipped, table_all, table_loso;
};

void evaluate(const Sample& s, const Rule& all, const Rule& fold, Evaluation& e) {
  const std::vector<StrokePoint>& points = s.drawing->strokes.front();
  e.shipped.add(s, classify(points, {}));
  e.all.add(s, classify(points, config_of(all, 0)));
  const ShapeClass held_out = classify(points, config_of(fold, 0));
  e.loso.add(s, held_out);
  e.per_label[s.drawing->label].add(s, held_out);
  e.former.add(s, classify(points, former_config(0)));
  for (std::size_t i = 0; i < kCells; ++i) {
    const std::vector<StrokePoint> p = rescaled(points, kSizesMm[i]);
    for (std::size_t j = 0; j < kCells; ++j) {
      RecognizerConfig shipped;
      shipped.pen_radius = kRadiiMm[j];
      e.table_shipped[i][j].add(s, classify(p, shipped));
      e.table_all[i][j].add(s, classify(p, config_of(all, kRadiiMm[j])));
      e.table_loso[i][j].add(s, classify(p, config_of(fold, kRadiiMm[j])));
    }
  }
}

void print_table(const char* title, const Table& t) {
  std::printf("  %s (shapes right / non-shapes snapped)\n  %-8s", title, "size");
  for (const double r : kRadiiMm) std::printf("   r = %-4.2f mm   ", r);
  std::printf("\n");
  for (std::size_t i = 0; i < kCells; ++i) {
    std::printf("  %3.0f mm  ", kSizesMm[i]);
    for (std::size_t j = 0; j < kCells; ++j) std::printf(" %s", t[i][j].text().c_str());
    std::printf("\n");
  }
}

void print_evaluation(const std::string& corpus, const Evaluation& e) {
  std::printf("-- %s --\n", corpus.c_str());
  std::printf("  default run (no pen given), shapes right / non-shapes snapped:\n");
  std::printf("    former rule min(5 R, 12.5%%) (baseline)  %s\n", e.former.text().c_str());
  std::printf("    shipped defaults (recognize.hpp)        %s\n", e.shipped.text().c_str());
  std::printf("    rule derived on all subjects            %s\n", e.all.text().c_str());
  std::printf("    leave-one-subject-out                   %s\n", e.loso.text().c_str());
  std::printf("  per class, leave-one-subject-out:\n");
  for (const auto& [label, t] : e.per_label) {
    std::printf("    %-18s %4d  %s\n", label.c_str(), t.shapes + t.non_shapes, t.text().c_str());
  }
  // What a user gets (the defaults in recognize.hpp), beside the derivation's rule.
  print_table("size x pen, shipped defaults", e.table_shipped);
  print_table("size x pen, rule derived on all subjects", e.table_all);
  print_table("size x pen, leave-one-subject-out", e.table_loso);
}

} // namespace

void print_accuracy(const std::vector<Drawing>& drawings, const AccuracyOptions& options) {
  const std::vector<Sample> samples = single_stroke_samples(drawings);
  if (samples.empty()) {
    std::printf("  no labelled single-stroke drawings\n");
    return;
  }
  const SubjectSweep sw = sweep(samples);
  print_sweep(sw);
  const Rule all = derive(sw, "");
  std::map<std::string, Rule> folds;
  double f_lo = 1, f_hi = 0, m_lo = 1, m_hi = 0;
  for (const auto& entry : sw) {
    const Rule r = derive(sw, entry.first);
    folds[entry.first] = r;
    f_lo = std::min(f_lo, r.f), f_hi = std::max(f_hi, r.f);
    m_lo = std::min(m_lo, r.f_max), m_hi = std::max(m_hi, r.f_max);
  }
  std::printf(
      "  derived on all %zu subjects: tolerance_size_fraction f = %.3f, max_tolerance_fraction "
      "f_max = %.3f (leaving one subject out: f in [%.3f, %.3f], f_max in [%.3f, %.3f])\n",
      sw.size(), all.f, all.f_max, f_lo, f_hi, m_lo, m_hi);
  if (options.derive_only) return;
  std::map<std::string, Evaluation> by_corpus;
  for (const Sample& s : samples) {
    evaluate(s, all, folds.at(s.drawing->subject), by_corpus[s.drawing->corpus]);
  }
  for (const auto& [corpus, e] : by_corpus) print_evaluation(corpus, e);
}

} // namespace penshape::bench
