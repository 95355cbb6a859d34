#pragma once
// recognize_union() with what tidy-up needs afterwards: the strokes as a certified union.
#include <functional>
#include <optional>
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

// What the caller keeps of a union: any shape, or a single arrow only (two strokes apart,
// kept_apart). For the latter the union is freeform at once when no single arrow certifies on
// it and is plausible: the same verdict for that caller, without fitting the other families.
enum class UnionUse { kAnyShape, kSingleArrowOnly };

UnionRecognition recognize_union_detail(std::span<const StrokeInput> strokes,
                                        const RecognizerConfig& config,
                                        UnionUse use = UnionUse::kAnyShape);

// The recognition `r` of a union read as its best alternative of a `kind` instead of its winner:
// the first alternative of that kind certified on the union and plausible becomes the winner (the
// winner goes first among the alternatives), with its rank; none when there is no such
// alternative. For a winner the grouping rules refuse while a shape of another kind also snaps.
struct AlternativeReading {
  Recognition recognition;
  double rank = 0.0;
};
std::optional<AlternativeReading> read_as(const Recognition& r,
                                          const std::function<bool(ShapeClass)>& kind);
// read_as an arrow (single or double): an open polyline in pieces that is an arrow's.
std::optional<AlternativeReading> read_as_arrow(const Recognition& r);

} // namespace penshape::recognize_detail
