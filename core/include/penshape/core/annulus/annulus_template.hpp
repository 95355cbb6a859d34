#pragma once
// Offset-polygon annulus placement (../shared/papers/offset-polygon-annulus-placement.txt):
// the template polygon, the annulus it defines, placements and the exact checks that certify them.
//
// The delta-annulus of a template P is the closed set of points at distance <= delta from the
// boundary of P (Definition 1). Two outer boundaries are offered for a convex P:
//   kRound       the true outer offset (segments and circular arcs): dist(x, P) <= delta;
//   kLinearized  the outer edges extended until they meet (the paper's linearized offset):
//                max_k (n_k . x - h_k) <= delta with unit outward normals n_k.
// The inner boundary is the inner offset I_{P,delta} (for convex P it is linear in both cases).
// For a simple (non-convex) template only kRound exists: the annulus is all points within delta of
// the boundary (Section 5).
//
// A placement maps a template point x to R(theta) x + t. The rotation is stored exactly as the
// rational point (c, s) = ((1 - u^2) / (1 + u^2), 2u / (1 + u^2)) with u = tan_half_theta, so a
// certificate can be rechecked exactly; theta = 2 atan(u) is for display.
//
// Number types: inputs are doubles; every double converts exactly to a rational. Searches run in
// doubles; every YES, every placement and every reported covered set is checked with exact
// rationals (GMP) against the exact definition above (a double filter skips the rationals when
// the answer is clear by far). NO answers and max-cover upper bounds are robust: the search runs
// with the annulus widened by a margin (annulus_margin, 1e-10 of the coordinates' magnitude), far
// above the rounding error of the search, and anchors a margin inside the widened annulus so that
// degenerate contacts (collinear integer samples) are decided with room to spare. Witnesses come
// from the same search with the annulus narrowed by the margin. Consequence: for delta within
// about a margin of the optimum the answer may be UNDECIDED, never wrong.
#include <cstddef>
#include <vector>

#include "penshape/core/deconstruct.hpp" // Answer, InvalidInput
#include "penshape/core/polygon_set.hpp" // PointD

namespace penshape::annulus {

enum class OuterOffset { kRound, kLinearized };
const char* to_string(OuterOffset o); // "round", "linearized"

// Explicit limits; exceeding one throws InvalidInput naming the limit.
struct Limits {
  std::size_t max_points = 200'000;
  std::size_t max_template_vertices = 4'096;
  std::size_t max_rotation_points = 5'000; // rotation algorithms are cubic in n
  double max_abs_coordinate = 1e12;        // |x|, |y| of vertices and points, and delta
};

// A validated template: vertices counterclockwise, no repeated vertices, finite coordinates.
// Convex templates are strictly convex (no collinear vertex triples); simple templates have no
// self-intersections. Build one with make_convex_template / make_simple_template.
class TemplatePolygon {
 public:
  [[nodiscard]] const std::vector<PointD>& vertices() const { return vertices_; }
  [[nodiscard]] bool convex() const { return convex_; }
  [[nodiscard]] std::size_t size() const { return vertices_.size(); }

 private:
  friend TemplatePolygon make_convex_template(std::vector<PointD>, const Limits&);
  friend TemplatePolygon make_simple_template(std::vector<PointD>, const Limits&);
  std::vector<PointD> vertices_;
  bool convex_ = false;
};

// Throws InvalidInput when: fewer than 3 vertices, a non-finite or too large coordinate, two equal
// consecutive vertices, three collinear consecutive vertices, a reflex vertex ("the template is
// not convex") — every test exact. Clockwise input is reversed to counterclockwise.
TemplatePolygon make_convex_template(std::vector<PointD> vertices, const Limits& limits = {});

// Any simple polygon (convex ones too). Throws InvalidInput when edges cross or touch other than
// at shared endpoints, on zero area, and for the same input problems as above. The algorithms do
// not need the paper's delta-wide condition (they sweep every offset piece), it only bounds cost.
TemplatePolygon make_simple_template(std::vector<PointD> vertices, const Limits& limits = {});

struct Placement {
  double tx = 0.0;
  double ty = 0.0;
  double tan_half_theta = 0.0; // exact rotation parameter u (0 = no rotation)
  double theta = 0.0;          // radians, 2 atan(u), display only
};

// Throws InvalidInput for an empty point set, a non-finite/too large coordinate, too many points,
// and a delta that is not finite, too large or negative; the message names the point and field.
void validate_points(const std::vector<PointD>& points, const Limits& limits = {});
void validate_delta(double delta, const Limits& limits = {});

// Exact: is point q in the delta-annulus of the placed template? (rationals, no rounding)
bool annulus_contains_exactly(const TemplatePolygon& p, OuterOffset outer, double delta,
                              const Placement& placement, PointD q);

// Exact: indices of the points in the delta-annulus of the placed template, ascending.
std::vector<std::size_t> covered_exactly(const TemplatePolygon& p, OuterOffset outer, double delta,
                                         const Placement& placement,
                                         const std::vector<PointD>& points);

// Smallest delta whose annulus at this placement contains every point: max over points of the
// distance to the boundary (linearized: |max_k n_k . x - h_k| outside). Doubles, relative error
// about 1e-15 of the coordinates' magnitude.
double width_at(const TemplatePolygon& p, OuterOffset outer, const Placement& placement,
                const std::vector<PointD>& points);

// The widening used for robust NO answers: 1e-10 times (template extent + delta + the largest
// coordinate magnitude among `points`). A NO means no placement exists even for delta + margin.
double annulus_margin(const TemplatePolygon& p, double delta, const std::vector<PointD>& points);

} // namespace penshape::annulus
