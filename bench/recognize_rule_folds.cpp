// Per-writer (leave-one-subject-out) choice of the classifier's rule thresholds
// (recognize_rule_folds.hpp). The fits of a drawing are made once; only the plausibility rules
// (evaluate) run again per threshold, as recognize() runs them (no ink, no skeleton: the bench's
// drawings have neither).
#include "recognize_rule_folds.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "made_shapes.hpp"
#include "recognize/classify/classifier.hpp"
#include "recognize/fitting/dot.hpp"
#include "recognize/fitting/prepared_stroke.hpp"
#include "recognize_accuracy.hpp"

namespace penshape::bench {
namespace {

namespace rd = recognize_detail;

// A drawing ready for the rules: its fits made once. targets null: a non-shape. corners: a made
// polygon's, which the answer must have too (0: any).
struct Item {
  std::string subject, row;
  const std::set<std::string>* targets = nullptr;
  int corners = 0;
  rd::PreparedStroke stroke;
  std::vector<rd::Fit> fits;
  ToleranceChoice tolerance;
};

struct Count {
  int shapes = 0, right = 0, non_shapes = 0, snapped = 0;
  void add(const Count& c) {
    shapes += c.shapes, right += c.right, non_shapes += c.non_shapes, snapped += c.snapped;
  }
  [[nodiscard]] double right_rate() const { return shapes ? 1.0 * right / shapes : 1.0; }
  [[nodiscard]] double snap_rate() const { return non_shapes ? 1.0 * snapped / non_shapes : 0.0; }
  // What a fold maximises: shapes named right minus non-shapes snapped.
  [[nodiscard]] double score() const { return right_rate() - snap_rate(); }
  [[nodiscard]] std::string text() const {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%5.1f%% / %4.1f%%", 100 * right_rate(), 100 * snap_rate());
    return buf;
  }
};

// A swept threshold: its grid (the first value turns the rule off) and where it goes (a rule
// threshold, or a RecognizerConfig field the rules read).
struct Sweep {
  const char* name;
  std::vector<double> grid;
  double shipped;
  double scale; // printed as value / scale
  void (*set)(rd::RuleThresholds&, RecognizerConfig&, double);
};

const std::set<std::string> kDiamond{"diamond"};
const std::set<std::string> kSquare{"rectangle", "square", "quadrilateral"};
const std::set<std::string> kPolygon{"polygon", "regular_polygon"};

void add_item(std::vector<Item>& out, const Drawing& d, const std::vector<StrokePoint>& points,
              const std::set<std::string>* targets, const std::string& row, int corners = 0) {
  if (rd::is_dot(points)) return; // a dot is never a shape nor a snap: no rule decides it
  Item it{d.subject, row, targets, corners, {}, {}, choose_tolerance(points, {})};
  const RecognizerConfig config;
  it.stroke = rd::prepare(points, rd::thinning_tolerance(config, it.tolerance.epsilon));
  it.fits = rd::fit_all(it.stroke, config, it.tolerance.epsilon);
  out.push_back(std::move(it));
}

std::vector<Item> items_of(const std::vector<Drawing>& drawings) {
  std::vector<Item> out;
  for (const auto& [drawing, targets] : single_stroke_samples(drawings)) {
    const Drawing& d = *drawing;
    const std::vector<StrokePoint>& p = d.strokes.front();
    add_item(out, d, p, targets, d.corpus + (targets ? " shape " : " non-shape ") + d.label);
    for (int n = 5; targets != nullptr && d.label == "circle" && n <= 8; ++n) {
      add_item(out, d, cases::made_polygon(p, n, 0.5), &kPolygon,
               d.corpus + " made polygon of " + std::to_string(n), n);
    }
    if (d.label != "rectangle" && d.label != "square") continue;
    add_item(out, d, cases::on_corner(p, cases::kDiamondAcross), &kDiamond,
             d.corpus + " made diamond");
    add_item(out, d, cases::on_corner(p, 1.0), &kSquare, d.corpus + " made square on a corner");
  }
  return out;
}

// The winning fit, or nothing (freeform).
std::optional<rd::Fit> winner(const Item& it, const rd::RuleThresholds& rules,
                              const RecognizerConfig& config) {
  std::vector<rd::Scored> scored = rd::evaluate(it.stroke, it.fits, it.tolerance.epsilon,
                                                it.tolerance.pen_radius, config, rules);
  if (scored.empty() || !scored.front().snap) return std::nullopt;
  return std::move(scored.front().fit);
}

bool right_answer(const Item& it, const rd::Fit& got) {
  if (it.corners > 0) return cases::is_polygon_of(got.shape, got.params, it.corners);
  return it.targets->contains(to_string(got.shape));
}

Count count_of(const Item& it, const std::optional<rd::Fit>& got) {
  Count c;
  if (it.targets != nullptr) {
    c.shapes = 1, c.right = got && right_answer(it, *got) ? 1 : 0;
  } else {
    c.non_shapes = 1, c.snapped = got ? 1 : 0;
  }
  return c;
}

// by_subject[subject][k], by_row[row][k]: counts at the grid's k-th value.
struct SweepCounts {
  std::map<std::string, std::vector<Count>> by_subject, by_row;
};

SweepCounts run_sweep(const std::vector<Item>& items, const Sweep& sw) {
  SweepCounts out;
  for (const Item& it : items) {
    std::vector<Count>& subject = out.by_subject[it.subject];
    std::vector<Count>& row = out.by_row[it.row];
    subject.resize(sw.grid.size()), row.resize(sw.grid.size());
    for (std::size_t k = 0; k < sw.grid.size(); ++k) {
      rd::RuleThresholds rules;
      RecognizerConfig config;
      sw.set(rules, config, sw.grid[k]);
      const Count c = count_of(it, winner(it, rules, config));
      subject[k].add(c), row[k].add(c);
    }
  }
  return out;
}

// The grid index chosen on every subject but `left_out`: best score, ties to the shipped value.
std::size_t choose(const SweepCounts& counts, const Sweep& sw, const std::string& left_out) {
  std::vector<Count> total(sw.grid.size());
  for (const auto& [subject, row] : counts.by_subject) {
    if (subject == left_out) continue;
    for (std::size_t k = 0; k < row.size(); ++k) total[k].add(row[k]);
  }
  std::size_t best = 0;
  double best_score = -std::numeric_limits<double>::infinity(), best_gap = 0;
  for (std::size_t k = 0; k < total.size(); ++k) {
    const double score = total[k].score(), gap = std::abs(sw.grid[k] - sw.shipped);
    if (score > best_score + 1e-12 || (std::abs(score - best_score) <= 1e-12 && gap < best_gap)) {
      best = k, best_score = score, best_gap = gap;
    }
  }
  return best;
}

std::size_t index_of(const Sweep& sw, double value) {
  for (std::size_t k = 0; k < sw.grid.size(); ++k) {
    if (sw.grid[k] == value) return k;
  }
  return 0;
}

void print_grid(const SweepCounts& counts, const Sweep& sw) {
  std::vector<Count> total(sw.grid.size());
  for (const auto& [subject, row] : counts.by_subject) {
    for (std::size_t k = 0; k < row.size(); ++k) total[k].add(row[k]);
  }
  for (std::size_t k = 0; k < sw.grid.size(); ++k) {
    std::printf("    %8.3f%s  %s\n", sw.grid[k] / sw.scale, k == 0 ? " (off)" : "      ",
                total[k].text().c_str());
  }
}

void print_folds(const SweepCounts& counts, const Sweep& sw) {
  std::map<double, int> chosen;
  Count held_out, off, shipped;
  const std::size_t ship = index_of(sw, sw.shipped);
  for (const auto& [subject, row] : counts.by_subject) {
    const std::size_t k = choose(counts, sw, subject);
    ++chosen[sw.grid[k] / sw.scale];
    held_out.add(row[k]), off.add(row[0]), shipped.add(row[ship]);
  }
  std::printf("    per-fold choice (value: folds):");
  for (const auto& [value, n] : chosen) std::printf(" %.3f: %d", value, n);
  std::printf(
      "\n    rule off %s | shipped %.3f %s | held out (each writer at the value chosen "
      "without them) %s\n",
      off.text().c_str(), sw.shipped / sw.scale, shipped.text().c_str(), held_out.text().c_str());
  std::printf("    classes the rule changes (rule off -> shipped value, all writers):\n");
  for (const auto& [row, c] : counts.by_row) {
    if (c[0].right == c[ship].right && c[0].snapped == c[ship].snapped) continue;
    std::printf("      %-40s %s -> %s\n", row.c_str(), c[0].text().c_str(), c[ship].text().c_str());
  }
}

} // namespace

void print_rule_folds(const std::vector<Drawing>& drawings) {
  const std::vector<Item> items = items_of(drawings);
  const double degree = rd::kDegree;
  const Sweep sweeps[] = {
      {"kDiamondSkew (deg): a rhombus is a diamond when its angles are this far from 90",
       {0.0, 5 * degree, 10 * degree, 12.5 * degree, 15 * degree, 17.5 * degree, 20 * degree,
        25 * degree},
       rd::kDiamondSkew,
       degree,
       [](rd::RuleThresholds& r, RecognizerConfig&, double v) { r.diamond_skew = v; }},
      {"kMaxBacktrack: the stroke runs back along the shape over at most this share",
       {std::numeric_limits<double>::infinity(), 0.05, 0.075, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4},
       rd::kMaxBacktrack,
       1.0,
       [](rd::RuleThresholds& r, RecognizerConfig&, double v) { r.max_backtrack = v; }},
      {"kMinSharpCornerShare: a polygon's corners are drawn sharp when the stroke turns this share",
       {std::numeric_limits<double>::infinity(), 0.3, 0.4, 0.5, 0.6, 0.7, 0.8},
       rd::kMinSharpCornerShare,
       1.0,
       [](rd::RuleThresholds& r, RecognizerConfig&, double v) { r.min_sharp_corner_share = v; }},
      {"kSharpPolygonSlack: a circle gives way to a sharp polygon fitting this much looser",
       {1.0, 1.1, 1.2, 1.3, 1.5},
       rd::kSharpPolygonSlack,
       1.0,
       [](rd::RuleThresholds& r, RecognizerConfig&, double v) { r.sharp_polygon_slack = v; }},
      {"kMinFittedCornerShare: a fitted corner is drawn when the stroke turns this share there",
       {0.0, 0.2, 0.3, 0.4, 0.5, 0.6},
       rd::kMinFittedCornerShare,
       1.0,
       [](rd::RuleThresholds& r, RecognizerConfig&, double v) { r.min_fitted_corner_share = v; }},
      {"kMinModelCornerShare: a model shape's corners are turned at, on the mean, by this share",
       {0.0, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55},
       rd::kMinModelCornerShare,
       1.0,
       [](rd::RuleThresholds& r, RecognizerConfig&, double v) { r.min_model_corner_share = v; }},
      {"kMinMissedCornerTurn: a polygon misses a corner where the stroke turns this share",
       {std::numeric_limits<double>::infinity(), 0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0},
       rd::kMinMissedCornerTurn,
       1.0,
       [](rd::RuleThresholds& r, RecognizerConfig&, double v) { r.min_missed_corner_turn = v; }},
      {"kMinFlatCornerTurn: a sharp polygon's corner near its neighbours' chord is turned this "
       "share of a regular polygon's turn",
       {std::numeric_limits<double>::infinity(), 0.3, 0.4, 0.5, 0.6, 0.75, 1.0},
       rd::kMinFlatCornerTurn,
       1.0,
       [](rd::RuleThresholds& r, RecognizerConfig&, double v) { r.min_flat_corner_turn = v; }},
      {"straight_fraction: a segment or polyline certifies within this share of epsilon",
       {std::numeric_limits<double>::infinity(), 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.6},
       RecognizerConfig{}.straight_fraction,
       1.0,
       [](rd::RuleThresholds&, RecognizerConfig& c, double v) { c.straight_fraction = v; }},
  };
  std::printf(
      "== rule thresholds per held-out writer: %zu drawings (shapes right / non-shapes "
      "snapped, shipped tolerance) ==\n",
      items.size());
  if (items.empty()) {
    std::printf("  no labelled drawings (../shared/data/strokes missing): nothing to choose on\n");
    return;
  }
  for (const Sweep& sw : sweeps) {
    std::printf("  %s\n", sw.name);
    const SweepCounts counts = run_sweep(items, sw);
    print_grid(counts, sw);
    print_folds(counts, sw);
  }
  std::fflush(stdout);
}

} // namespace penshape::bench
