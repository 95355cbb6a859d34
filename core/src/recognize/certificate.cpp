// Certified upper bound on the Hausdorff distance between the stroke's path and a clean shape's
// path by Lipschitz sampling (see the argument in penshape/core/recognize.hpp).
#include "certificate.hpp"

#include <cmath>
#include <vector>

#include "segment_index.hpp"

namespace penshape::recognize_detail {
namespace {

constexpr double kMaxSamples = 50'000.0;

// Nearest distance from p to the stroke polyline, pruning segments whose bounding box is farther
// than the best distance so far (starting from the segment that was nearest last time). Linear
// in the stroke's segments per query: the unthinned baseline.
struct StrokeDistance {
  std::span<const PointD> stroke;
  std::size_t hint = 0;

  double operator()(PointD p) {
    if (stroke.size() == 1) return distance(p, stroke[0]);
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
    return best;
  }
};

// The largest distance from the shape's samples to the stroke through a grid of the stroke's
// segments: a query only needs to know whether a sample is farther than the worst so far, so
// the grid search stops at the first segment within it.
double farthest_from_stroke(std::span<const PointD> stroke, const std::vector<PointD>& samples,
                            double cell) {
  if (stroke.size() == 1) {
    double worst = 0.0;
    for (const PointD& s : samples) worst = std::max(worst, distance(s, stroke[0]));
    return worst;
  }
  std::vector<Segment> segments;
  segments.reserve(stroke.size() - 1);
  for (std::size_t i = 0; i + 1 < stroke.size(); ++i)
    segments.push_back({stroke[i], stroke[i + 1]});
  // About 64 x 64 cells at most: the index costs no more to build than a few queries.
  const SegmentIndex index(std::move(segments), cell, 4096);
  double worst = 0.0;
  for (const PointD& s : samples) worst = std::max(worst, index.nearest_above(s, worst));
  return worst;
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
  double h = epsilon / 6.0;
  h = std::max({h, stroke_len / kMaxSamples, shape_len / kMaxSamples, 1e-12 * extent});
  cert.sample_spacing = h;

  // Exact for polylines and circles; for ellipses the distance to a point on the ellipse, which
  // bounds the distance from above.
  auto to_shape = [&](PointD p) { return shape.distance_to(p); };

  // sup over the stroke path of the distance to the shape.
  double worst = stroke.size() == 1 ? to_shape(stroke[0]) : 0.0;
  for (std::size_t i = 0; i + 1 < stroke.size(); ++i) {
    const double len = distance(stroke[i], stroke[i + 1]);
    const auto pieces = static_cast<std::size_t>(std::max(1.0, std::ceil(len / h)));
    for (std::size_t k = 0; k <= pieces; ++k) {
      if (k == 0 && i > 0) continue; // shared with the previous segment's last sample
      const double f = static_cast<double>(k) / static_cast<double>(pieces);
      worst = std::max(worst, to_shape(stroke[i] + f * (stroke[i + 1] - stroke[i])));
    }
  }
  // sup over the shape path of the distance to the stroke.
  if (tau > 0.0) {
    worst = std::max(worst, farthest_from_stroke(stroke, shape.sample(h), epsilon / 2.0));
  } else {
    StrokeDistance to_stroke{stroke};
    for (const PointD& s : shape.sample(h)) worst = std::max(worst, to_stroke(s));
  }

  // Rounding: each distance is a few operations on coordinates of magnitude <= `magnitude`, so
  // its error is a small multiple of 2^-52 * magnitude (about 2.2e-16 * magnitude); the margin
  // 1e-13 * magnitude + 1e-9 * extent is far above that. The thinning's tests are the same
  // point-segment distances on the same coordinates: a second margin covers their rounding.
  double magnitude = extent;
  for (const PointD& p : stroke) magnitude = std::max({magnitude, std::abs(p.x), std::abs(p.y)});
  const double margin = (tau > 0.0 ? 2.0 : 1.0) * (1e-13 * magnitude + 1e-9 * extent);
  // H(A, B) <= H(A', B) + H(A, A') <= (worst + h / 2) + tau (recognize.hpp, "Dense strokes").
  cert.bound = worst + h / 2.0 + tau + margin;
  cert.certified = std::isfinite(cert.bound) && cert.bound <= epsilon;
  return cert;
}

} // namespace penshape::recognize_detail
