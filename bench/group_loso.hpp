#pragma once
// Leave-one-subject-out figures for the grouping and arrow thresholds picked on real strokes
// (group_recognize_bench --loso): each threshold is swept over a few values on the gestures of
// other people; for every writer the value is chosen on the other writers alone (most shapes
// right with their non-shape drawings snapped together <= 2%) and scored on the writer left out.
#include <filesystem>
#include <string>

namespace penshape::bench {

// Prints, per threshold, each value's figures on all writers, then the held-out figures beside
// the shipped value's. Nothing when the gestures are not there. `only`: the thresholds whose
// name starts with it (empty: all).
void print_group_loso(const std::filesystem::path& gestures_root, bool json,
                      const std::string& only = {});

} // namespace penshape::bench
