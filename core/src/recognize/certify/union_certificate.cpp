// Certified Hausdorff bound between a clean shape and the union of several strokes' paths.
#include "recognize/certify/union_certificate.hpp"

#include <cmath>

#include "recognize/certify/certified_distance.hpp"
#include "recognize/fitting/geometry.hpp"
#include "recognize/fitting/thin_path.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
UnionStroke prepare_union(const std::vector<std::vector<PointD>>& paths, double tau) {
  UnionStroke u;
  u.thinning = tau > 0.0 ? tau : 0.0;
  PointD lo{INFINITY, INFINITY};
  PointD hi{-INFINITY, -INFINITY};
  for (const std::vector<PointD>& path : paths) {
    for (const PointD& p : path) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    u.pieces.push_back(tau > 0.0 ? thin_path(path, tau) : path);
  }
  u.size = paths.empty() ? 0.0 : distance(lo, hi);
  return u;
}

double union_distance(const UnionStroke& u, PointD p) {
  double best = INFINITY;
  for (const std::vector<PointD>& piece : u.pieces) {
    best = std::min(best, polyline_distance(p, piece));
  }
  return best;
}

Certificate certify_union(const UnionStroke& u, const CleanShape& shape, double epsilon,
                          double pen_radius) {
  Certificate cert;
  cert.epsilon = epsilon;
  cert.pen_radius = pen_radius;
  double stroke_len = 0.0;
  for (const std::vector<PointD>& piece : u.pieces) stroke_len += path_length(piece);
  const double shape_len = path_length(shape.sample(u.size));
  // The spacing only sets the work: the half steps taken are added to the bound.
  const double h =
      std::max({epsilon / 6.0, stroke_len / kMaxSamples, shape_len / kMaxSamples, 1e-12 * u.size});
  cert.sample_spacing = h;
  const CertifiedShape certified(shape);

  // sup over every piece of the distance to the shape (each segment sampled, ends included),
  // certified (certified_distance.hpp).
  double worst = 0.0;
  std::vector<Segment> segments;
  for (const std::vector<PointD>& piece : u.pieces) {
    if (piece.size() == 1) {
      worst = std::max(worst, certified.upper(detail::enclose(piece[0]), piece[0]));
      segments.push_back({piece[0], piece[0]});
    }
    for (std::size_t i = 0; i + 1 < piece.size(); ++i) {
      segments.push_back({piece[i], piece[i + 1]});
      worst = std::max(worst, segment_to_shape(piece[i], piece[i + 1], h, certified));
    }
  }
  // sup over the shape of the distance to the nearest piece (segments only: no jumps).
  if (segments.empty()) {
    cert.bound = INFINITY;
    cert.method = "path";
    return cert;
  }
  const SegmentIndex index(std::move(segments), epsilon / 2.0, 4096);
  worst = std::max(worst, certified.farthest_from(index, h));
  // + tau: thin_path decides H(A_i, A_i') <= tau with the same kernel.
  cert.bound = sum_up({worst, u.thinning, certified.end_slack()});
  cert.certified = std::isfinite(cert.bound) && cert.bound <= epsilon;
  cert.method = "path";
  return cert;
}

} // namespace penshape::recognize_detail
