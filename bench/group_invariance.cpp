// Drawings of several strokes under transforms (group_invariance.hpp).
#include "group_invariance.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "group_gesture_figures.hpp"
#include "stroke_corpora.hpp"

namespace penshape::bench {
namespace {

struct Transform {
  const char* name;
  std::function<void(StrokePoint&)> apply;
};

// The groups and their classes, as one line: "arrow(2) segment(1)".
std::string answer_text(const std::vector<GroupedShape>& groups) {
  std::string out;
  for (const GroupedShape& g : groups) {
    out +=
        std::string(to_string(g.recognition.shape)) + "(" + std::to_string(g.strokes.size()) + ") ";
  }
  return out;
}

struct Scored {
  const Drawing* drawing;
  GestureKind kind;
  std::string as_drawn;
};

struct Row {
  int shapes = 0, right = 0, non_shapes = 0, snapped = 0, changed = 0;
  void add(const Scored& s, const std::vector<GroupedShape>& got) {
    const bool hit = gesture_hit(s.kind, got);
    if (s.kind == GestureKind::kNonShape) {
      ++non_shapes, snapped += hit ? 1 : 0;
    } else if (s.kind != GestureKind::kChevron) {
      ++shapes, right += hit ? 1 : 0;
    }
    changed += answer_text(got) != s.as_drawn ? 1 : 0;
  }
  void print(const char* name, std::size_t n) const {
    std::printf("  %-22s %6.1f%%  %6.1f%%  %5d of %zu\n", name, 100.0 * right / shapes,
                100.0 * snapped / non_shapes, changed, n);
  }
};

std::vector<Transform> transforms() {
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  return {{"moved by 10^6", [](StrokePoint& q) { q.x += 1e6, q.y -= 1e6; }},
          {"scaled by 1000", [](StrokePoint& q) { q.x *= 1000, q.y *= 1000; }},
          {"turned by 90 deg",
           [](StrokePoint& q) {
             q = {-q.y, q.x, q.t};
           }},
          {"turned by 30 deg", [c, s](StrokePoint& q) {
             q = {c * q.x - s * q.y, s * q.x + c * q.y, q.t};
           }}};
}

} // namespace

void print_group_invariance(const std::filesystem::path& gestures_root) {
  const std::vector<Drawing> drawings = load_gestures(gestures_root);
  std::vector<Scored> scored;
  Row as_drawn;
  for (const Drawing& d : drawings) {
    const GestureKind kind = gesture_kind(d);
    if (kind == GestureKind::kNone || d.strokes.size() < 2) continue;
    const std::vector<GroupedShape> got = recognize_gesture(d);
    scored.push_back({&d, kind, answer_text(got)});
    as_drawn.add(scored.back(), got);
  }
  if (scored.empty()) return;
  std::printf("\ninvariance: %zu drawings of several strokes by other people\n", scored.size());
  std::printf("  %-22s %7s  %7s  %s\n", "transform", "shapes", "non-sh.", "answers changed");
  as_drawn.print("as drawn", scored.size());
  for (const Transform& t : transforms()) {
    Row row;
    for (const Scored& s : scored) {
      Drawing moved = *s.drawing;
      for (std::vector<StrokePoint>& stroke : moved.strokes) {
        for (StrokePoint& q : stroke) t.apply(q);
      }
      row.add(s, recognize_gesture(moved));
    }
    row.print(t.name, scored.size());
    std::fflush(stdout);
  }
}

} // namespace penshape::bench
