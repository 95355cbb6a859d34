// Live candidates (see live_candidate.hpp).
#include "live_candidate.hpp"

namespace penshape::recognize_detail {

bool convex_polygon(ShapeClass c) {
  switch (c) {
    case ShapeClass::kTriangle:
    case ShapeClass::kQuadrilateral:
    case ShapeClass::kRectangle:
    case ShapeClass::kSquare:
    case ShapeClass::kDiamond:
    case ShapeClass::kRegularPolygon:
      return true;
    default:
      return false;
  }
}

LiveCandidate LiveCandidate::make(Scored&& scored, const PreparedStroke& s, double epsilon,
                                  double coordinate_magnitude) {
  LiveCandidate c;
  c.rank = scored.rank;
  c.epsilon = epsilon;
  c.family = family_of(scored.fit);
  if (convex_polygon(scored.fit.shape)) {
    try {
      const annulus::TemplatePolygon t = annulus::make_convex_template(scored.fit.params.vertices);
      c.online.emplace(t, annulus::OuterOffset::kRound, epsilon, coordinate_magnitude);
      // Seeded with the fit points (48 along the stroke at the fit; the certificate already
      // covers the fitted path at the fitted placement), then fed every later point.
      for (const PointD& p : s.fit_points) c.online->add(p);
      c.alive = c.online->answer() != Answer::kNo; // a certified fit cannot be a NO
    } catch (const InvalidInput&) {
      c.online.reset(); // a degenerate template: fall back to the fixed placement
    }
  }
  c.fit = std::move(scored.fit);
  return c;
}

bool LiveCandidate::accept(PointD p) {
  if (!alive) return false;
  if (online) {
    alive = online->add(p) != Answer::kNo;
  } else {
    alive = fit.clean.distance_to(p) <= epsilon;
  }
  return alive;
}

bool LiveCandidate::accept_all(std::span<const PointD> points) {
  for (const PointD& p : points) {
    if (!accept(p)) return false;
  }
  return alive;
}

PointD LiveCandidate::shift() const {
  if (!online || online->answer() != Answer::kYes) return {};
  return {online->placement().tx, online->placement().ty};
}

Fit LiveCandidate::placed() const {
  Fit f = fit;
  if (!online || online->answer() != Answer::kYes) return f;
  const PointD t = shift();
  for (PointD& v : f.clean.path) v = v + t;
  for (PointD& v : f.params.vertices) v = v + t;
  f.params.center = f.params.center + t;
  return f;
}

} // namespace penshape::recognize_detail
