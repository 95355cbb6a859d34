// Per-class figures of the shipped recognizer (recognize_classes.hpp).
//
// Diamonds: no shared corpus holds one-stroke diamonds, so real one-stroke rectangles ($1, and
// the gestures' squares) are mapped onto them (made_shapes.hpp): a rhombus of 62 and 118 degrees,
// a flowchart decision, or a square on its corner, which must stay a square. Polygons of 5..8
// corners: no shared corpus holds drawn ones, so real one-stroke circles are made polygons (the
// writer's wobble and closure kept, corners added) and must be named `polygon` or
// `regular_polygon` with as many corners. "simplified": the shapes (and the made hexagons) as
// sketch collections store drawings (made_shapes.hpp, sketch_simplified: a 255-unit box,
// Douglas-Peucker at 2 units).
#include "recognize_classes.hpp"

#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "made_shapes.hpp"
#include "recognize_accuracy.hpp"

namespace penshape::bench {
namespace {

struct Count {
  int drawings = 0, right = 0;
  [[nodiscard]] double rate() const { return drawings ? 100.0 * right / drawings : 0.0; }
};

struct Row {
  std::string name;
  Count count;
};

// Stars drawn in one stroke (an outline or crossing itself) have no class: they must stay ink.
// Printed here only: the accuracy tables and the tolerance derivation keep their non-shapes.
const std::set<std::string> kStars{"star", "five_point_star", "six_point_star"};

void tally(std::map<std::string, Count>& rows, const std::string& key, bool right) {
  Count& c = rows[key];
  ++c.drawings;
  c.right += right ? 1 : 0;
}

// The answer's class, and its corner count where it has corners (a made octagon read as a
// pentagon).
void print_miss(const Drawing& d, const std::string& row, const Recognition& got) {
  char answer[48];
  std::snprintf(answer, sizeof answer, "%s", to_string(got.shape));
  if (!got.params.vertices.empty()) {
    std::snprintf(answer, sizeof answer, "%s %zu", to_string(got.shape),
                  got.params.vertices.size());
  }
  std::printf("    wrong: %-28s %-17s %s\n", row.c_str(), answer, d.file.c_str());
}

} // namespace

void print_classes(const std::vector<Drawing>& drawings, const ClassOptions& options) {
  std::map<std::string, Count> rows; // "corpus/label" -> right (shapes) or left as ink
  const std::set<std::string> diamond{"diamond"};
  const std::set<std::string> square{"square", "rectangle", "quadrilateral"};
  for (const Drawing& d : drawings) {
    if (d.strokes.size() != 1) continue;
    const std::set<std::string>* targets = shape_targets(d.label);
    if (targets == nullptr && !is_non_shape(d.label) && !kStars.contains(d.label)) continue;
    const Recognition got = recognize(d.strokes.front());
    const bool right = targets != nullptr
                           ? targets->contains(to_string(got.shape))
                           : got.shape == ShapeClass::kFreeform || got.shape == ShapeClass::kDot;
    const std::string key = d.corpus + (targets ? " shape " : " non-shape ") + d.label;
    tally(rows, key, right);
    if (!right && options.list_wrong) print_miss(d, key, got);
    if (cases::sketch_simplified(d.strokes.front()).size() > 1) {
      const ShapeClass simple = recognize(cases::sketch_simplified(d.strokes.front())).shape;
      tally(rows, d.corpus + " simplified " + d.label,
            targets != nullptr ? targets->contains(to_string(simple))
                               : simple == ShapeClass::kFreeform || simple == ShapeClass::kDot);
    }
    if (targets != nullptr && d.label == "circle") {
      const std::vector<StrokePoint> hexagon = cases::made_polygon(d.strokes.front(), 6, 0.5);
      tally(rows, d.corpus + " simplified made polygon of 6",
            cases::is_polygon_of(recognize(cases::sketch_simplified(hexagon)), 6));
      for (int n = 5; n <= 8; ++n) {
        const Recognition made = recognize(cases::made_polygon(d.strokes.front(), n, 0.5));
        const bool ok = cases::is_polygon_of(made, n);
        const std::string row = "polygon of " + std::to_string(n) + " (circle)";
        tally(rows, d.corpus + " made " + row, ok);
        if (!ok && options.list_wrong) print_miss(d, row, made);
      }
    }
    if (targets == nullptr || (d.label != "rectangle" && d.label != "square")) continue;
    for (const auto& [across, name, want] :
         {std::tuple{cases::kDiamondAcross, "diamond (rectangle, 45, 0.6)", &diamond},
          std::tuple{1.0, "square on a corner (45)", &square}}) {
      const Recognition made = recognize(cases::on_corner(d.strokes.front(), across));
      const bool ok = want->contains(to_string(made.shape));
      tally(rows, d.corpus + " made " + name, ok);
      if (!ok && options.list_wrong) print_miss(d, name, made);
    }
  }
  std::printf("  per class, shipped defaults (shapes: named right; non-shapes: left as ink)\n");
  for (const auto& [key, c] : rows) {
    std::printf("    %-44s %5d  %5.1f%%\n", key.c_str(), c.drawings, c.rate());
  }
}

} // namespace penshape::bench
