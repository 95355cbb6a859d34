// Grouping figures on other people's drawings (group_gesture_figures.hpp).
#include "group_gesture_figures.hpp"

#include <cstdio>
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

void print_row(const std::string& what, const Rate& r, const char* target, bool json) {
  if (json) {
    std::printf("{\"row\":\"%s\",\"right\":%d,\"total\":%d,\"percent\":%.2f}\n", what.c_str(),
                r.hits, r.total, r.percent());
  } else {
    std::printf("%-44s %6.1f%%  (%d / %d)   target %s\n", what.c_str(), r.percent(), r.hits,
                r.total, target);
  }
}

} // namespace

void print_group_gesture_figures(const std::filesystem::path& gestures_root, bool json) {
  const std::vector<Drawing> drawings = load_gestures(gestures_root);
  if (drawings.empty()) return;
  std::map<std::string, Rate> shapes;     // "square in 2 strokes", "arrow in 1 stroke"
  std::map<std::string, Rate> non_shapes; // snapped together, by class
  Rate shapes_all, non_shapes_all;
  for (const Drawing& d : drawings) {
    const bool square = d.label == "square";
    const bool arrow = d.label == "arrow_right" || d.label == "arrowhead";
    const bool non_shape = kNonShapes.contains(d.label) && d.strokes.size() >= 2;
    if (!square && !arrow && !non_shape) continue;
    const std::vector<GroupedShape> out = recognize_strokes(inputs_of(d));
    if (non_shape) {
      bool merged = false;
      for (const GroupedShape& g : out) {
        merged = merged || (g.strokes.size() > 1 && g.recognition.shape != ShapeClass::kFreeform);
      }
      non_shapes[d.label].add(merged);
      non_shapes_all.add(merged);
      continue;
    }
    const std::set<std::string>& targets = square ? kRectangle : kArrow;
    const bool ok = out.size() == 1 && targets.contains(to_string(out[0].recognition.shape));
    const std::size_t n = d.strokes.size();
    shapes[std::string(square ? "square" : "arrow") + " in " + std::to_string(n) + " stroke" +
           (n == 1 ? "" : "s") + " (" + source_of(d) + ")"]
        .add(ok);
    shapes_all.add(ok);
  }
  if (!json) std::printf("\nother people's drawings (%s; never tuned on):\n", "gestures");
  print_row("shapes right (squares, arrows), all strokes", shapes_all, ">= 95%", json);
  for (const auto& [k, r] : shapes) print_row("  " + k, r, "", json);
  print_row("non-shape drawings snapped together", non_shapes_all, "<= 2%", json);
  for (const auto& [k, r] : non_shapes) print_row("  " + k, r, "", json);
}

} // namespace penshape::bench
