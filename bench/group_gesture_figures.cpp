// Grouping figures on other people's drawings (group_gesture_figures.hpp).
#include "group_gesture_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "penshape/core/group_recognize.hpp"
#include "stroke_corpora.hpp"

namespace penshape::bench {
namespace {

const std::set<std::string> kRectangle{"rectangle", "square", "quadrilateral"};
const std::set<std::string> kArrow{"arrow"};
// Classes drawn in several strokes that are no shape together.
const std::set<std::string> kNonShapes{"T",    "X",         "D",         "P",
                                       "null", "half_note", "pitchfork", "asterisk",
                                       "H",    "I",         "letter_A",  "stick_figure"};

struct Rate {
  int hits = 0, total = 0;
  void add(bool hit) { hits += hit ? 1 : 0, ++total; }
  [[nodiscard]] double percent() const { return total ? 100.0 * hits / total : 0.0; }
};

// A figure with its per-writer rates, to show the spread over writers beside the whole.
struct Figure {
  Rate all;
  std::map<std::string, Rate> by_subject;
  void add(const std::string& subject, bool hit) {
    all.add(hit);
    by_subject[subject].add(hit);
  }
};

std::vector<StrokeInput> inputs_of(const Drawing& d) {
  std::vector<StrokeInput> in;
  for (const auto& s : d.strokes) in.push_back({s, nullptr, nullptr, 0.0, {}});
  return in;
}

// The source ("MMG", "MMG+", "LowVision") of a gesture subject "gestures/<source>-<writer>".
std::string source_of(const Drawing& d) {
  const std::string s = d.subject.substr(d.subject.find('/') + 1);
  return s.substr(0, s.rfind('-'));
}

std::string strokes_of(std::size_t n) {
  std::string s = std::to_string(n);
  s.append(n == 1 ? " stroke" : " strokes");
  return s;
}

void print_row(const std::string& what, const Rate& r, const char* target, bool json) {
  if (json) {
    std::printf("{\"row\":\"%s\",\"right\":%d,\"total\":%d,\"percent\":%.2f}\n", what.c_str(),
                r.hits, r.total, r.percent());
  } else {
    std::printf("%-44s %6.1f%%  (%d / %d)   target %s\n", what.c_str(), r.percent(), r.hits,
                r.total, target);
  }
}

// The whole, then the writers' median and worst (best for a rate that must stay low).
void print_figure(const std::string& what, const Figure& f, const char* target, bool low,
                  bool json) {
  print_row(what, f.all, target, json);
  std::vector<double> p;
  for (const auto& [s, r] : f.by_subject) p.push_back(r.percent());
  if (p.size() < 2 || json) return;
  std::sort(p.begin(), p.end());
  std::printf("%-44s median %.1f%%, worst %.1f%% (%zu writers)\n", "    per writer",
              p[p.size() / 2], low ? p.back() : p.front(), p.size());
}

struct Tally {
  Figure shapes, non_shapes, chevrons_as_arrows;
  std::map<std::string, Figure> rows; // "square in 2 strokes (LowVision)", ...
  std::map<std::string, int> misses;  // "arrow in 2 strokes (MMG) -> polyline polyline"
  std::filesystem::path svg_dir;      // when set, every miss is drawn there
};

// A miss drawn to look at: the strokes (grey, numbered at their start) and each group's clean
// shape (red), with the answer as the title.
void draw_miss(const std::filesystem::path& dir, const Drawing& d,
               const std::vector<GroupedShape>& out, const std::string& answer) {
  double xl = INFINITY, yl = INFINITY, xh = -INFINITY, yh = -INFINITY;
  for (const auto& s : d.strokes) {
    for (const StrokePoint& q : s) {
      xl = std::min(xl, q.x), yl = std::min(yl, q.y), xh = std::max(xh, q.x),
      yh = std::max(yh, q.y);
    }
  }
  const double pad = 0.1 * std::max(xh - xl, yh - yl) + 1.0;
  std::ofstream svg(dir / (std::filesystem::path(d.file).stem().string() + ".svg"));
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='400' height='400' viewBox='" << xl - pad
      << ' ' << yl - 2 * pad << ' ' << xh - xl + 2 * pad << ' ' << yh - yl + 3 * pad
      << "'><rect x='-1e5' y='-1e5' width='2e5' height='2e5' fill='white'/>\n<text x='" << xl - pad
      << "' y='" << yl - pad << "' font-size='" << pad / 2 << "'>" << answer << "</text>\n";
  const double w = 0.01 * std::max(xh - xl, yh - yl);
  for (std::size_t k = 0; k < d.strokes.size(); ++k) {
    svg << "<polyline fill='none' stroke='black' stroke-opacity='0.4' stroke-width='" << 3 * w
        << "' points='";
    for (const StrokePoint& q : d.strokes[k]) svg << q.x << ',' << q.y << ' ';
    svg << "'/><text fill='blue' font-size='" << pad / 2 << "' x='" << d.strokes[k].front().x
        << "' y='" << d.strokes[k].front().y << "'>" << k + 1 << "</text>\n";
  }
  for (const GroupedShape& g : out) {
    // Which strokes each group holds and its vertices (an arrow's: tail, tip, barb ends).
    svg << "<!-- " << to_string(g.recognition.shape) << " of strokes";
    for (const std::size_t k : g.strokes) svg << ' ' << k + 1;
    svg << ", vertices";
    for (const PointD& q : g.recognition.params.vertices) svg << ' ' << q.x << ',' << q.y;
    svg << " -->\n";
    const Recognition& r = g.recognition;
    for (const std::vector<PointD>& piece : clean_pieces(r.shape, r.params, r.clean)) {
      svg << "<polyline fill='none' stroke='red' stroke-width='" << w << "' points='";
      for (const PointD& q : piece) svg << q.x << ',' << q.y << ' ';
      svg << "'/>\n";
    }
  }
  svg << "</svg>\n";
}

std::string answer_of(const std::vector<GroupedShape>& out) {
  std::string s = std::to_string(out.size());
  s.append(out.size() == 1 ? " group:" : " groups:");
  for (const GroupedShape& g : out) {
    s.append(" ").append(to_string(g.recognition.shape));
    if (g.strokes.size() > 1) s.append("(").append(std::to_string(g.strokes.size())).append(")");
  }
  return s;
}

// Why the union of an arrow's strokes is not an arrow: its best arrow candidate's refusal.
std::string why_no_arrow(const Drawing& d, bool arrow) {
  if (!arrow) return {};
  const Recognition r = recognize_union(inputs_of(d));
  for (const Candidate& c : r.alternatives) {
    if (c.shape != ShapeClass::kArrow) continue;
    if (!c.rejected.empty()) return " [" + c.rejected + "]";
    return c.certificate.certified ? " [arrow ranked lower]" : " [arrow not certified]";
  }
  return r.shape == ShapeClass::kArrow ? " [union is an arrow]" : " [no arrow candidate]";
}

} // namespace

GestureKind gesture_kind(const Drawing& d) {
  // LowVision's "arrow_right" is the touch gesture ">" (a chevron, no shaft): never an arrow.
  if (d.label == "arrow_right") return GestureKind::kChevron;
  if (d.label == "square") return GestureKind::kSquare;
  if (d.label == "arrowhead") return GestureKind::kArrow;
  if (kNonShapes.contains(d.label) && d.strokes.size() >= 2) return GestureKind::kNonShape;
  return GestureKind::kNone;
}

bool gesture_hit(GestureKind kind, const std::vector<GroupedShape>& out) {
  if (kind == GestureKind::kNonShape || kind == GestureKind::kChevron) {
    bool hit = false;
    for (const GroupedShape& g : out) {
      hit = hit || (kind == GestureKind::kChevron
                        ? kArrow.contains(to_string(g.recognition.shape))
                        : g.strokes.size() > 1 && g.recognition.shape != ShapeClass::kFreeform);
    }
    return hit;
  }
  const std::set<std::string>& targets = kind == GestureKind::kSquare ? kRectangle : kArrow;
  return out.size() == 1 && targets.contains(to_string(out[0].recognition.shape));
}

std::vector<GroupedShape> recognize_gesture(const Drawing& d) {
  return recognize_strokes(inputs_of(d));
}

namespace {

void tally(const Drawing& d, Tally& t) {
  const GestureKind kind = gesture_kind(d);
  const bool chevron = kind == GestureKind::kChevron;
  const bool square = kind == GestureKind::kSquare;
  const bool arrow = kind == GestureKind::kArrow;
  const bool non_shape = kind == GestureKind::kNonShape;
  if (kind == GestureKind::kNone) return;
  const std::vector<GroupedShape> out = recognize_gesture(d);
  if (chevron) {
    t.chevrons_as_arrows.add(d.subject, gesture_hit(kind, out));
    ++t.misses["chevron (" + source_of(d) + ") -> " + answer_of(out)];
    return;
  }
  if (non_shape) {
    const bool merged = gesture_hit(kind, out);
    t.non_shapes.add(d.subject, merged);
    t.rows["non-shape " + d.label + " (" + source_of(d) + ")"].add(d.subject, merged);
    if (merged) {
      ++t.misses[d.label + " in " + strokes_of(d.strokes.size()) + " -> " + answer_of(out)];
      if (!t.svg_dir.empty()) draw_miss(t.svg_dir, d, out, d.label + " -> " + answer_of(out));
    }
    return;
  }
  const bool ok = gesture_hit(kind, out);
  const std::string row = std::string(square ? "square" : "arrow") + " in " +
                          strokes_of(d.strokes.size()) + " (" + source_of(d) + ")";
  t.rows[row].add(d.subject, ok);
  t.shapes.add(d.subject, ok);
  if (ok) return;
  const std::string answer = answer_of(out) + why_no_arrow(d, arrow);
  ++t.misses[row + " -> " + answer];
  if (!t.svg_dir.empty()) draw_miss(t.svg_dir, d, out, row + " -> " + answer);
}

} // namespace

void print_group_gesture_figures(const std::filesystem::path& gestures_root, bool json,
                                 const std::filesystem::path& svg_dir, const std::string& only) {
  const std::vector<Drawing> drawings = load_gestures(gestures_root);
  if (drawings.empty()) return;
  Tally t;
  t.svg_dir = svg_dir;
  for (const Drawing& d : drawings) {
    if (only.empty() || d.label == only) tally(d, t);
  }
  if (!json) std::printf("\nother people's drawings (%s; never tuned on):\n", "gestures");
  print_figure("shapes right (squares, arrows), all strokes", t.shapes, ">= 95%", false, json);
  for (const auto& [k, r] : t.rows) {
    if (k.rfind("non-shape", 0) != 0) print_figure("  " + k, r, "", false, json);
  }
  print_figure("non-shape drawings snapped together", t.non_shapes, "<= 2%", true, json);
  for (const auto& [k, r] : t.rows) {
    if (k.rfind("non-shape", 0) == 0) print_row("  " + k.substr(10), r.all, "", json);
  }
  print_figure("chevrons '>' read as arrows (LowVision)", t.chevrons_as_arrows, "<= 2%", true,
               json);
  if (json) return;
  std::printf("\nanswers on other people's drawings (misses; chevrons: every answer):\n");
  for (const auto& [k, n] : t.misses) std::printf("  %4d  %s\n", n, k.c_str());
}

} // namespace penshape::bench
