#pragma once
// recognize_union() with what tidy-up needs afterwards: the strokes as a certified union.
#include <span>
#include <vector>

#include "penshape/core/group_recognize.hpp"
#include "recognize/certify/union_certificate.hpp"

namespace penshape::recognize_detail {

struct UnionRecognition {
  Recognition recognition;
  UnionStroke strokes; // the union the winner was certified on (thinned pieces)
  double rank = 0.0;   // the winner's rank (classifier.hpp), +inf for freeform
};

// The samples' positions without consecutive repeats.
std::vector<PointD> distinct_path(const std::vector<StrokePoint>& samples);

UnionRecognition recognize_union_detail(std::span<const StrokeInput> strokes,
                                        const RecognizerConfig& config);

// The union read as its best arrow instead of its winner: the first alternative that is an arrow
// certified on the union and plausible becomes the winner (the winner goes first among the
// alternatives, the rank is the arrow's). False, and `u` unchanged, when there is none. For a
// winner the grouping rules refuse (an open polyline in pieces) while an arrow also snaps.
bool read_as_arrow(UnionRecognition& u);

} // namespace penshape::recognize_detail
