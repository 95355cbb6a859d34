// Minimum-width annulus placement of a polygon snap (see annulus_polish.hpp).
#include "recognize/classify/annulus_polish.hpp"

#include "penshape/core/annulus/translation.hpp"
#include "recognize/certify/certificate.hpp"
#include "recognize/classify/classifier.hpp"

namespace penshape::recognize_detail {

bool polish_with_annulus(const PreparedStroke& s, Scored& winner, const RecognizerConfig& config) {
  if (!convex_polygon(winner.fit.shape)) return false;
  const Certificate& before = winner.candidate.certificate;
  annulus::MinWidthResult placed;
  try {
    const annulus::TemplatePolygon t = annulus::make_convex_template(winner.fit.params.vertices);
    annulus::MinWidthOptions options;
    options.relative_tolerance = 1e-3; // far below the tolerance; keeps the bisection short
    options.max_decisions = 30;
    placed = annulus::min_width_translation(t, annulus::OuterOffset::kRound, s.fit_points, options);
  } catch (const InvalidInput&) {
    return false; // a degenerate (non strictly convex) polygon: keep the fitted placement
  }
  const PointD shift{placed.placement.tx, placed.placement.ty};
  Fit moved = winner.fit;
  for (PointD& v : moved.clean.path) v = v + shift;
  for (PointD& v : moved.params.vertices) v = v + shift;
  moved.params.center = moved.params.center + shift;
  const Certificate after = certify(s, moved.clean, before.epsilon, before.pen_radius);
  if (!after.certified || after.bound >= before.bound) return false;
  (void)config;
  winner.fit = moved;
  winner.candidate.params = moved.params;
  winner.candidate.clean = moved.clean.path;
  winner.candidate.certificate = after;
  winner.candidate.rms = rms_distance(s.fit_points, moved.clean);
  return true;
}

} // namespace penshape::recognize_detail
