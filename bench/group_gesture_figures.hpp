#pragma once
// group_recognize_bench on drawings by writers the grouping rules were never tuned on (the
// gestures of ../shared/data/strokes/gestures): squares in 1-5 strokes, arrows in 1-3 strokes,
// and drawings of several strokes that are no shape (letters, notes, a stick figure), which must
// not be snapped together. Per class and per source beside the whole.
#include <filesystem>
#include <string>

namespace penshape::bench {

// Prints the figures; nothing when the gestures are not there. With svg_dir, every miss is also
// drawn there; with `only`, only the drawings of that class are scored.
void print_group_gesture_figures(const std::filesystem::path& gestures_root, bool json,
                                 const std::filesystem::path& svg_dir = {},
                                 const std::string& only = {});

} // namespace penshape::bench
