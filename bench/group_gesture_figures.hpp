#pragma once
// group_recognize_bench on drawings by writers the grouping rules were never tuned on (the
// gestures of ../shared/data/strokes/gestures): squares in 1-5 strokes, arrows in 1-3 strokes,
// and drawings of several strokes that are no shape (letters, notes, a stick figure), which must
// not be snapped together. Per class and per source beside the whole.
#include <filesystem>
#include <string>
#include <vector>

#include "penshape/core/group_recognize.hpp"
#include "stroke_corpora.hpp"

namespace penshape::bench {

// Prints the figures; nothing when the gestures are not there. With svg_dir, every miss is also
// drawn there; with `only`, only the drawings of that class are scored.
void print_group_gesture_figures(const std::filesystem::path& gestures_root, bool json,
                                 const std::filesystem::path& svg_dir = {},
                                 const std::string& only = {});

// What a gesture drawing is scored as: a shape of several strokes (squares, arrows), a drawing
// of several strokes that is no shape, LowVision's chevron '>', or not scored here.
enum class GestureKind { kNone, kSquare, kArrow, kNonShape, kChevron };
GestureKind gesture_kind(const Drawing& d);
// The drawing's strokes through recognize_strokes().
std::vector<GroupedShape> recognize_gesture(const Drawing& d);
// Shapes: one group of the right class. Non-shapes: some strokes snapped together. Chevrons:
// read as an arrow.
bool gesture_hit(GestureKind kind, const std::vector<GroupedShape>& out);

} // namespace penshape::bench
