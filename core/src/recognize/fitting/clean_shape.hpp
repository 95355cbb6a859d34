#pragma once
// The clean shape a candidate proposes, in the form the certificate and the fitters measure:
// a polyline (segments, polylines, polygons) or several polylines (an arrow whose shaft stops
// short of its tip: the shaft and the head), a circular arc or full circle, or an elliptic arc
// or full ellipse.
#include <algorithm>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "penshape/core/recognize.hpp"
#include "recognize/fitting/geometry.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

struct CleanShape {
  enum class Kind { kPolyline, kCircle, kEllipse };
  Kind kind = Kind::kPolyline;
  std::vector<PointD> path; // kPolyline: vertices in order; closed shapes repeat the first
  // kPolyline of several pieces: for each i listed (ascending), the step path[i] -> path[i + 1]
  // joins two pieces and is no part of the shape. Every piece has >= 2 vertices. The shape is
  // the union of the pieces, so the distance to it is the least over the pieces, and a bound
  // over its points is the greatest over the pieces: each user below skips the jumps.
  std::vector<std::size_t> jumps;
  PointD center;   // kCircle, kEllipse
  double rx = 0.0; // circle radius; ellipse semi-axis along `rotation`
  double ry = 0.0; // ellipse semi-axis across `rotation`
  double rotation = 0.0;
  double t0 = 0.0;                       // parameter range [t0, t0 + sweep]; sweep
  double sweep = 2.0 * std::numbers::pi; // may be negative; |sweep| = 2 pi: full curve

  // The whole curve, decided exactly: 2 pi is irrational, the double D nearest it lies below it
  // and the next double above it. So |sweep| > D covers a full turn exactly; |sweep| == D (how
  // every full circle and ellipse is written) misses an arc of 2 pi - D < 2.5e-16 rad, less than
  // the end rounding CertifiedShape::end_slack already adds for a full curve (speed times
  // ulp(D), about 8.9e-16), so it is taken as the whole curve. Anything shorter is an arc.
  [[nodiscard]] bool full_curve() const { return std::abs(sweep) >= 2.0 * std::numbers::pi; }
  [[nodiscard]] PointD at(double t) const; // curve point at parameter t (not for kPolyline)
  // Whether the step path[i] -> path[i + 1] is a segment of the shape (kPolyline).
  [[nodiscard]] bool joined(std::size_t i) const {
    return std::find(jumps.begin(), jumps.end(), i) == jumps.end();
  }
  // The length of a polyline's pieces (the jumps left out).
  [[nodiscard]] double length() const;
  // The path sampled with arc-length steps <= h (polyline vertices always included; a jump is
  // not sampled, so consecutive samples across it are two pieces' ends).
  [[nodiscard]] std::vector<PointD> sample(double h) const;
  // Distance from p to the shape: exact for polylines and circular arcs; for (full) ellipses
  // the distance to a point of the ellipse found by Newton's method, an upper bound that is
  // exact when Newton converges.
  [[nodiscard]] double distance_to(PointD p) const;
};

// The clean shape a recognition's class and parameters describe (recognize.hpp, ShapeParams).
// Throws InvalidInput for freeform and degenerate parameters.
CleanShape clean_shape_of(ShapeClass shape, const ShapeParams& params);

// An arrow's shaft: the straight segment (bulge 0) or the circular arc through tail and tip
// whose midpoint is `bulge` to the left of the chord, as kShaftChords chords. The certificate is
// of these chords (the clean path); with |bulge| <= chord / 4 (what the fitter allows) each chord
// strays from the exact arc by under 0.2% of the chord.
// With `bends` (ShapeParams::shaft_bends) the shaft is the polyline tail -> bends -> tip and the
// bulge is ignored (clean_shape_of refuses both at once).
std::vector<PointD> shaft_path(PointD tail, PointD tip, double bulge,
                               const std::vector<PointD>& bends = {});
// An arrow's clean path from its vertices (group_recognize.hpp, "Arrows"); throws InvalidInput
// for the wrong vertex count. With `shaft_end` (a single arrow's straight or bent shaft) the
// path is the shaft tail -> bends -> shaft_end, then the head barb 1 -> tip -> barb 2, and the
// step between them is a jump (arrow_jump).
std::vector<PointD> arrow_path(ShapeClass shape, const std::vector<PointD>& vertices, double bulge,
                               const std::vector<PointD>& bends = {},
                               const std::optional<PointD>& shaft_end = std::nullopt);
// The jump of an arrow_path with a shaft_end: after the shaft's last vertex (empty without one).
std::vector<std::size_t> arrow_jumps(const std::vector<PointD>& bends,
                                     const std::optional<PointD>& shaft_end);

// Distance from p to a circular arc (exact formula).
double arc_distance(PointD p, const CleanShape& circle);
// Distance from p to a point of the full ellipse near its foot point (an upper bound).
double ellipse_distance(PointD p, const CleanShape& ellipse);

// Sampson's first-order distance to an ellipse: fast, accurate near it, not a bound.
double approximate_ellipse_distance(PointD p, const CleanShape& ellipse);

// Max of distance_to over `points` (for ellipses: of the Sampson distance); the fitters'
// objective, an estimate, never a certificate.
double max_distance(std::span<const PointD> points, const CleanShape& shape);

// Root-mean-square distance of `points` to the shape (Sampson distance for ellipses).
double rms_distance(std::span<const PointD> points, const CleanShape& shape);

} // namespace penshape::recognize_detail
