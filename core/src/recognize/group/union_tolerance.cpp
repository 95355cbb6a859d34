// A union's tolerance from its strokes' bounding boxes (union_tolerance.hpp).
#include "recognize/group/union_tolerance.hpp"

#include <algorithm>
#include <limits>

#include "recognize/classify/classifier.hpp"

namespace penshape::recognize_detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void include(SampleBox& box, PointD lo, PointD hi) {
  box.lo = {std::min(box.lo.x, lo.x), std::min(box.lo.y, lo.y)};
  box.hi = {std::max(box.hi.x, hi.x), std::max(box.hi.y, hi.y)};
}

} // namespace

ToleranceChoice union_tolerance(std::span<const SampleBox> boxes, const RecognizerConfig& config) {
  SampleBox box{{kInf, kInf}, {-kInf, -kInf}};
  for (const SampleBox& b : boxes) include(box, b.lo, b.hi);
  if (!(box.lo.x <= box.hi.x)) return choose_tolerance({}, config); // no samples at all
  return tolerance_for_box(box.lo, box.hi, config);
}

} // namespace penshape::recognize_detail
