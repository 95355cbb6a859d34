#pragma once
// Other people's drawings of several strokes (group_gesture_figures.hpp) moved far, scaled and
// turned (group_recognize_bench --invariance): how many answers (the groups and their classes)
// differ from the drawings' own, and the shapes right and non-shapes snapped together either way.
#include <filesystem>

namespace penshape::bench {

void print_group_invariance(const std::filesystem::path& gestures_root);

} // namespace penshape::bench
