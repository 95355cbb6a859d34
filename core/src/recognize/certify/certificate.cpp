// Certified upper bound on the Hausdorff distance between the stroke's path and a clean shape's
// path by Lipschitz sampling (see the argument in penshape/core/recognize.hpp). Doubles choose the
// samples and propose the nearest parts; every distance that enters the bound is an interval
// upper bound (certified_distance.hpp), and so are the half sampling steps added to it.
#include "recognize/certify/certificate.hpp"

#include <cmath>
#include <vector>

#include "recognize/certify/certified_distance.hpp"
#include "recognize/fitting/geometry.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

// The stroke segment nearest to p, pruning segments whose bounding box is farther than the best
// distance so far (starting from the segment that was nearest last time). Linear in the stroke's
// segments per query: the unthinned baseline. A proposal: the bound is evaluated on it.
struct StrokeDistance {
  std::span<const PointD> stroke;
  std::size_t hint = 0;

  Segment operator()(PointD p, double /*floor*/) {
    double best = segment_distance(p, stroke[hint], stroke[hint + 1]);
    for (std::size_t i = 0; i + 1 < stroke.size(); ++i) {
      const PointD a = stroke[i];
      const PointD b = stroke[i + 1];
      const double lox = std::min(a.x, b.x), hix = std::max(a.x, b.x);
      const double loy = std::min(a.y, b.y), hiy = std::max(a.y, b.y);
      const double bx = std::max({lox - p.x, p.x - hix, 0.0});
      const double by = std::max({loy - p.y, p.y - hiy, 0.0});
      if (bx >= best || by >= best) continue;
      const double d = segment_distance(p, a, b);
      if (d < best) {
        best = d;
        hint = i;
      }
    }
    return {stroke[hint], stroke[hint + 1]};
  }
};

// sup over the shape of the distance to the stroke (certified).
double shape_to_stroke(std::span<const PointD> stroke, const CertifiedShape& shape, double h,
                       double cell, bool indexed) {
  if (stroke.size() == 1) {
    const Segment point{stroke[0], stroke[0]};
    return shape.farthest_from([&](PointD, double) { return point; }, h);
  }
  if (!indexed) {
    StrokeDistance to_stroke{stroke};
    return shape.farthest_from([&](PointD q, double floor) { return to_stroke(q, floor); }, h);
  }
  std::vector<Segment> segments;
  segments.reserve(stroke.size() - 1);
  for (std::size_t i = 0; i + 1 < stroke.size(); ++i)
    segments.push_back({stroke[i], stroke[i + 1]});
  // About 64 x 64 cells at most: the index costs no more to build than a few queries. A query
  // only needs a segment within the worst distance so far: the grid search stops at it.
  const SegmentIndex index(std::move(segments), cell, 4096);
  return shape.farthest_from(index, h);
}

} // namespace

Certificate certify(const PreparedStroke& prepared, const CleanShape& shape, double epsilon,
                    double pen_radius) {
  const std::span<const PointD> stroke(prepared.points);
  const double extent = prepared.size;
  const double tau = prepared.thinning;
  Certificate cert;
  cert.epsilon = epsilon;
  cert.pen_radius = pen_radius;
  const double stroke_len = path_length(stroke);
  std::vector<PointD> probe = shape.sample(extent); // coarse, only to measure the shape's length
  const double shape_len = path_length(probe);
  // The spacing only sets the work: the half steps actually taken are added to the bound.
  double h = epsilon / 6.0;
  h = std::max({h, stroke_len / kMaxSamples, shape_len / kMaxSamples, 1e-12 * extent});
  cert.sample_spacing = h;
  const CertifiedShape certified(shape);

  // sup over the stroke path of the distance to the shape.
  double worst = stroke.size() == 1 ? certified.upper(detail::enclose(stroke[0]), stroke[0]) : 0.0;
  for (std::size_t i = 0; i + 1 < stroke.size(); ++i) {
    worst = std::max(worst, segment_to_shape(stroke[i], stroke[i + 1], h, certified));
  }
  // sup over the shape path of the distance to the stroke.
  worst = std::max(worst, shape_to_stroke(stroke, certified, h, epsilon / 2.0, tau > 0.0));
  // H(A, B) <= H(A', B) + H(A, A') <= worst + tau (recognize.hpp, "Dense strokes"); thin_path
  // decides H(A, A') <= tau with the same kernel.
  cert.bound = sum_up({worst, tau, certified.end_slack()});
  cert.certified = std::isfinite(cert.bound) && cert.bound <= epsilon;
  return cert;
}

} // namespace penshape::recognize_detail
