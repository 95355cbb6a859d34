// Ink-level Hausdorff certificate by 2-D grid sampling (argument in
// penshape/core/ink_certificate.hpp).
#include "ink_certificate.hpp"

#include <cmath>
#include <numbers>

namespace penshape::recognize_detail {
namespace {

constexpr double kHalfDiagonal = 0.70710678118654757; // >= 1/sqrt(2) (rounded up)
// Curves (box, ellipse chords) are sampled with at most about this many points.
constexpr double kMaxCurveSamples = 20'000.0;

// The clean shape's distance function as the grid needs it: an upper bound everywhere (for the
// Q side) and a test "is the true distance <= rho?" that never says no wrongly (for the
// clean-ink side).
class ShapeDistance {
 public:
  ShapeDistance(const CleanShape& shape, double h) : shape_(shape) {
    if (shape.kind != CleanShape::Kind::kEllipse) return;
    // The ellipse sampled with arc-length steps <= hs: every point of it is within hs / 2 of a
    // sample, so d(g, ellipse) >= d(g, sample chords) - hs / 2.
    hs_ =
        std::max(h / 4.0, 2.0 * std::numbers::pi * std::max(shape.rx, shape.ry) / kMaxCurveSamples);
    const std::vector<PointD> pts = shape.sample(hs_);
    std::vector<Segment> chords;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) chords.push_back({pts[i], pts[i + 1]});
    chords_ = SegmentIndex(std::move(chords), 2.0 * h);
    cos_ = std::cos(shape.rotation);
    sin_ = std::sin(shape.rotation);
  }

  // True when upper() is the exact distance (up to rounding): polylines and circular arcs.
  [[nodiscard]] bool exact() const { return shape_.kind != CleanShape::Kind::kEllipse; }

  // >= d(g, C): exact for polylines and circular arcs, a point on the ellipse otherwise.
  [[nodiscard]] double upper(PointD g) const { return shape_.distance_to(g); }

  // False only when d(g, C) > rho.
  [[nodiscard]] bool maybe_within(PointD g, double rho) const {
    if (shape_.kind != CleanShape::Kind::kEllipse) return shape_.distance_to(g) <= rho;
    // Quick rejection: with F(p) = x^2/a^2 + y^2/b^2 - 1 (ellipse frame) and e the foot point,
    // |F(g)| = |F(g) - F(e)| <= d * max |grad F| over the disk of radius d around g. If d <= rho,
    // that max is <= 2 sqrt((|x| + rho)^2 / a^4 + (|y| + rho)^2 / b^4), so a larger |F(g)| / rho
    // proves d > rho.
    const PointD d = g - shape_.center;
    const double x = std::abs(cos_ * d.x + sin_ * d.y);
    const double y = std::abs(-sin_ * d.x + cos_ * d.y);
    const double a2 = shape_.rx * shape_.rx, b2 = shape_.ry * shape_.ry;
    const double f = std::abs(x * x / a2 + y * y / b2 - 1.0);
    const double gx = (x + rho) / a2, gy = (y + rho) / b2;
    if (f > 2.0 * rho * std::sqrt(gx * gx + gy * gy) * (1.0 + 1e-9)) return false;
    return chords_.any_within(g, rho + hs_ / 2.0);
  }

 private:
  const CleanShape& shape_;
  double hs_ = 0.0;
  SegmentIndex chords_{{}, 1.0};
  double cos_ = 1.0, sin_ = 0.0;
};

} // namespace

InkRegion prepare_ink(const InkPolygon& ink, double epsilon) {
  if (ink.region.empty()) throw InvalidInput("ink certificate: the ink polygon is empty");
  if (!(epsilon > 0) || !std::isfinite(epsilon)) {
    throw InvalidInput("ink certificate: epsilon must be positive and finite");
  }
  InkRegion q;
  q.hausdorff_bound = ink.hausdorff_bound;
  std::vector<Segment> edges;
  q.lo = {INFINITY, INFINITY};
  q.hi = {-INFINITY, -INFINITY};
  auto add_ring = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const PointD a = to_double(ring[i]);
      const PointD b = to_double(ring[(i + 1) % ring.size()]);
      if (!std::isfinite(a.x) || !std::isfinite(a.y)) {
        throw InvalidInput("ink certificate: an ink polygon coordinate is not finite");
      }
      edges.push_back({a, b});
      q.lo = {std::min(q.lo.x, a.x), std::min(q.lo.y, a.y)};
      q.hi = {std::max(q.hi.x, a.x), std::max(q.hi.y, a.y)};
      q.magnitude = std::max({q.magnitude, std::abs(a.x), std::abs(a.y)});
    }
  };
  for (const PolygonWithHoles& p : ink.region.polygons) {
    add_ring(p.outer);
    for (const Ring& hole : p.holes) add_ring(hole);
  }
  if (edges.empty()) throw InvalidInput("ink certificate: the ink polygon has no edges");
  // Spacing: epsilon / 10, coarser when the sampled box (Q's box grown by about 1.3 epsilon on
  // each side, the most a certifiable shape's ink can reach) would exceed the point budget.
  const double w = q.hi.x - q.lo.x + 2.6 * epsilon, ht = q.hi.y - q.lo.y + 2.6 * epsilon;
  q.h = std::max(epsilon / kInkGridDivisions, std::sqrt(w * ht / kMaxInkGridPoints));
  q.h = std::max(q.h, 1e-12 * std::max(w, ht));
  q.origin = q.lo;
  // Rows of the grid that meet Q's box, with the x where each edge crosses the row (half-open in
  // y so that a vertex on the row counts once for the two edges meeting there).
  q.first_row = static_cast<std::int64_t>(std::floor((q.lo.y - q.origin.y) / q.h));
  const auto last_row = static_cast<std::int64_t>(std::ceil((q.hi.y - q.origin.y) / q.h));
  q.rows.assign(static_cast<std::size_t>(last_row - q.first_row + 1), {});
  for (const Segment& e : edges) {
    const double ylo = std::min(e.a.y, e.b.y), yhi = std::max(e.a.y, e.b.y);
    if (ylo == yhi) continue;
    const auto j0 = static_cast<std::int64_t>(std::ceil((ylo - q.origin.y) / q.h)) - 1;
    const auto j1 = static_cast<std::int64_t>(std::floor((yhi - q.origin.y) / q.h)) + 1;
    for (std::int64_t j = std::max(j0, q.first_row); j <= std::min(j1, last_row); ++j) {
      const double y = q.origin.y + static_cast<double>(j) * q.h;
      if (y < ylo || y >= yhi) continue;
      const double t = (y - e.a.y) / (e.b.y - e.a.y);
      q.rows[static_cast<std::size_t>(j - q.first_row)].push_back(e.a.x + t * (e.b.x - e.a.x));
    }
  }
  for (auto& row : q.rows) std::sort(row.begin(), row.end());
  q.edges = SegmentIndex(std::move(edges), 2.0 * q.h);
  return q;
}

Certificate certify_ink(const InkRegion& q, const CleanShape& shape, double epsilon,
                        double pen_radius) {
  Certificate cert;
  cert.method = "ink";
  cert.epsilon = epsilon;
  cert.pen_radius = pen_radius;
  const double h = q.h;
  cert.sample_spacing = h;
  const double r = pen_radius;

  // The clean ink's box: C sampled with steps <= hs (every point of C within hs / 2 of a
  // sample), grown by r + hs / 2.
  // Polylines: the vertices give the box exactly. Curves: at most kMaxCurveSamples samples.
  double hs = 0.0;
  if (shape.kind != CleanShape::Kind::kPolyline) {
    const double length = std::abs(shape.sweep) * std::max(shape.rx, shape.ry);
    hs = std::max(h / 4.0, length / kMaxCurveSamples);
  }
  PointD lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  double magnitude = q.magnitude;
  for (const PointD& p : hs > 0 ? shape.sample(hs) : shape.path) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double grow = r + hs / 2.0;
  lo = {lo.x - grow, lo.y - grow};
  hi = {hi.x + grow, hi.y + grow};
  magnitude = std::max({magnitude, std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)});
  const PointD ulo{std::min(lo.x, q.lo.x), std::min(lo.y, q.lo.y)};
  const PointD uhi{std::max(hi.x, q.hi.x), std::max(hi.y, q.hi.y)};
  const double extent = std::hypot(uhi.x - ulo.x, uhi.y - ulo.y);
  // Rounding: every distance below is a few operations on coordinates of magnitude <=
  // `magnitude`, its error a small multiple of 2^-52 * magnitude; this margin is far above.
  const double margin = 1e-13 * magnitude + 1e-9 * extent;
  if (!std::isfinite(extent)) {
    cert.bound = INFINITY;
    return cert;
  }
  // A clean ink reaching more than epsilon + 2h beyond Q's box has a point farther than epsilon
  // from Q: it cannot certify. Its bound is the union box's diagonal (any point of either region
  // is within it of any point of the other), honest and cheap.
  const double reach = epsilon + 2.0 * h;
  if (lo.x < q.lo.x - reach || lo.y < q.lo.y - reach || hi.x > q.hi.x + reach ||
      hi.y > q.hi.y + reach) {
    cert.bound = extent + q.hausdorff_bound + margin;
    return cert;
  }

  const ShapeDistance to_shape(shape, h);
  // Grid points within h/sqrt(2) of every point of the union box.
  const auto i0 = static_cast<std::int64_t>(std::floor((ulo.x - q.origin.x) / h));
  const auto i1 = static_cast<std::int64_t>(std::ceil((uhi.x - q.origin.x) / h));
  const auto j0 = static_cast<std::int64_t>(std::floor((ulo.y - q.origin.y) / h));
  const auto j1 = static_cast<std::int64_t>(std::ceil((uhi.y - q.origin.y) / h));
  const double half_diag = kHalfDiagonal * h;
  const double rho = r + half_diag + margin; // grid points that can stand for the clean ink
  const double near_q = half_diag + margin;  // grid points that can stand for Q
  double worst_clean = 0.0; // max d(g, Q) over grid points standing for the clean ink
  double worst_ink = 0.0;   // max (d(g, C) - r) over grid points standing for Q
  static const std::vector<double> kNoCrossings;
  for (std::int64_t j = j0; j <= j1; ++j) {
    const double y = q.origin.y + static_cast<double>(j) * h;
    const std::int64_t k = j - q.first_row;
    const std::vector<double>& xs = k >= 0 && k < static_cast<std::int64_t>(q.rows.size())
                                        ? q.rows[static_cast<std::size_t>(k)]
                                        : kNoCrossings;
    std::size_t crossed = 0;
    for (std::int64_t i = i0; i <= i1; ++i) {
      const PointD g{q.origin.x + static_cast<double>(i) * h, y};
      while (crossed < xs.size() && xs[crossed] < g.x) ++crossed;
      const bool inside = (crossed % 2) == 1;
      if (inside) {
        // d(g, Q) = 0: stands for Q; for the clean ink it contributes 0.
        worst_ink = std::max(worst_ink, to_shape.upper(g) - r);
        continue;
      }
      if (!to_shape.exact()) {
        if (to_shape.maybe_within(g, rho)) {
          worst_clean = std::max(worst_clean, q.edges.nearest_above(g, worst_clean));
        }
        if (q.edges.any_within(g, near_q)) {
          worst_ink = std::max(worst_ink, to_shape.upper(g) - r);
        }
        continue;
      }
      // Exact distance (polylines, circular arcs): one evaluation serves both sides, and the
      // Q-side test is skipped when it could not raise the maximum.
      const double dc = to_shape.upper(g);
      if (dc <= rho) worst_clean = std::max(worst_clean, q.edges.nearest_above(g, worst_clean));
      if (dc - r > worst_ink && q.edges.any_within(g, near_q)) worst_ink = dc - r;
    }
  }
  cert.bound = std::max(worst_clean, worst_ink) + half_diag + 2.0 * margin + q.hausdorff_bound;
  cert.certified = std::isfinite(cert.bound) && cert.bound <= epsilon;
  return cert;
}

} // namespace penshape::recognize_detail

namespace penshape {

Certificate certify_ink(const InkPolygon& ink, ShapeClass shape, const ShapeParams& params,
                        double pen_radius, double epsilon) {
  if (!(pen_radius >= 0) || !std::isfinite(pen_radius)) {
    throw InvalidInput("ink certificate: the pen radius must be finite and >= 0");
  }
  const recognize_detail::CleanShape clean = recognize_detail::clean_shape_of(shape, params);
  const recognize_detail::InkRegion q = recognize_detail::prepare_ink(ink, epsilon);
  return recognize_detail::certify_ink(q, clean, epsilon, pen_radius);
}

} // namespace penshape
