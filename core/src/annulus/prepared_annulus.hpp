#pragma once
// The delta-annulus of a template in the template's own frame, prepared for the sweeps: the
// boundary pieces a point can be anchored on, and the set of parameters along a piece where a
// second point (at offset d from the anchor) lies in the annulus. Doubles; certification happens
// in annulus_template.cpp with rationals.
#include <vector>

#include "intervals.hpp"
#include "penshape/core/annulus/annulus_template.hpp"
#include "penshape/core/bounding_box.hpp"
#include "penshape/core/point_arithmetic.hpp" // the kernel's PointD arithmetic

namespace penshape::annulus::detail {

using Box = BoxD;

// A template edge from a with vector v, unit outward normal n, support h = n . a.
struct Edge {
  PointD a;
  PointD v;
  PointD n;
  double h = 0.0;
  double len2 = 0.0;
};

// A boundary piece: a segment a -> b (parameter u in [0, 1]) or a circular arc around c of radius
// r (parameter phi in [phi0, phi1]).
struct Piece {
  bool arc = false;
  PointD a{}, b{};
  PointD c{};
  double r = 0.0;
  double phi0 = 0.0, phi1 = 0.0;
  [[nodiscard]] double lo() const { return arc ? phi0 : 0.0; }
  [[nodiscard]] double hi() const { return arc ? phi1 : 1.0; }
  [[nodiscard]] PointD at(double t) const;
  [[nodiscard]] Box box() const;
};

using Curve = std::vector<Piece>;

struct PreparedAnnulus {
  bool convex = true;
  OuterOffset outer = OuterOffset::kRound;
  double delta = 0.0;
  std::vector<Edge> edges;        // of the template
  PointD hole_centre{};           // a disk inside the open hole (membership delta): pieces
  double hole_radius = 0.0;       // inside it are rejected in O(1)
  bool has_hole = false;          // I_{P,delta} has interior (membership delta)
  std::vector<PointD> inner;      // I_{P,curve_delta} (convex), empty without interior
  std::vector<PointD> outer_poly; // linearized O_{P,delta} (convex)
  std::vector<Box> stadium_boxes; // per edge: bounding box of edge + disk(delta)
  Curve inner_curve;              // boundary of the hole (convex only)
  Curve outer_curve;              // outer boundary; for simple templates every offset piece
  double outer_stride = 1.0;      // 2 when outer_curve is a collection of separate pieces
  Box box{};                      // bounding box of the annulus
};

// Membership (member_set, has_hole, box) uses `delta`; the anchor curves and the offset polygons
// (inner, outer_poly) use `curve_delta`. The robust searches anchor on curves a margin inside the
// membership annulus, so that a point lying on an anchor curve's carrier line is decided with
// room to spare instead of by rounding.
PreparedAnnulus prepare(const TemplatePolygon& p, OuterOffset outer, double delta,
                        double curve_delta);
PreparedAnnulus prepare(const TemplatePolygon& p, OuterOffset outer, double delta);

// Deltas of the robust searches: NO and upper bounds anchor at delta + margin with membership at
// delta + 2 margin; witnesses anchor at delta - 2 margin with membership at delta - margin.
struct DeltaPair {
  double member;
  double curve;
};
inline DeltaPair widened(double delta, double margin) {
  return {delta + 2.0 * margin, delta + margin};
}
inline DeltaPair narrowed(double delta, double margin) {
  if (delta > 4.0 * margin) return {delta - margin, delta - 2.0 * margin};
  return {0.75 * delta, 0.5 * delta};
}
inline PreparedAnnulus prepare(const TemplatePolygon& p, OuterOffset outer, DeltaPair d) {
  return prepare(p, outer, d.member, d.curve);
}

// Parameters t of `piece` with piece.at(t) + d in the annulus (closed), sorted and disjoint.
IntervalSet member_set(const PreparedAnnulus& an, const Piece& piece, PointD d);

// The same measure from the prepared edges (doubles).
double prepared_measure(const PreparedAnnulus& an, PointD x);

// Distance-to-boundary measure in the template frame: the least delta whose annulus holds x.
double annulus_measure(const TemplatePolygon& p, OuterOffset outer, PointD x);

// Global parameter along a curve: piece index * stride + fraction inside the piece. Closed
// curves use stride 1 (piece ends meet); collections of separate pieces use stride 2, so that
// positions on different pieces never coincide in a sweep.
PointD curve_point(const Curve& c, double g, double stride = 1.0);

} // namespace penshape::annulus::detail
