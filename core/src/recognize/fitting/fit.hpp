#pragma once
// The fitters: each proposes the best shape of its family for a prepared stroke (or nothing when
// the family does not apply). Fits are estimates; only the certificate decides a snap.
#include <functional>
#include <optional>
#include <vector>

#include "recognize/fitting/clean_shape.hpp"
#include "recognize/fitting/prepared_stroke.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

struct Fit {
  ShapeClass shape = ShapeClass::kFreeform;
  CleanShape clean;
  ShapeParams params;
  double fit_error = 0.0; // the refinement objective at the result (a fast estimate)
};

// Minimax refinement of a parametrised shape (compass search on the parameter vector): the
// objective is the largest distance from the stroke's fit points to the shape, and from the
// shape's key points (corners, ends) to the stroke. This is the "min-width annulus" step for
// shapes of free size; a template-placement refiner (annulus package) can replace it for fixed
// templates.
struct Refinement {
  std::vector<double> params;
  double objective = 0.0;
};
using ShapeBuilder = std::function<std::optional<CleanShape>(const std::vector<double>&)>;
Refinement refine_minimax(const PreparedStroke& stroke, std::vector<double> params,
                          const ShapeBuilder& build, double initial_step, bool use_key_points);
// The refinement objective for one shape.
double fit_objective(const PreparedStroke& stroke, const CleanShape& shape, bool use_key_points);

// Corner search by dynamic programming on the fit points: indices of k vertices minimising the
// summed squared distance of the points to the chords. Open: the first and last points are
// vertices (k >= 2). Closed: the fit points are a cycle (k >= 3).
std::vector<std::size_t> open_corners(const std::vector<PointD>& pts, std::size_t k);
std::vector<std::size_t> closed_corners(const std::vector<PointD>& pts, std::size_t k);

// Total-least-squares line through points: a point on it and a unit direction.
struct Line {
  PointD point;
  PointD direction;
};
Line fit_line(std::span<const PointD> pts);

std::optional<Fit> fit_segment(const PreparedStroke& s);
std::optional<Fit> fit_polyline(const PreparedStroke& s, std::size_t segments);
ShapeClass polygon_class(std::size_t corners);
std::optional<Fit> fit_polygon(const PreparedStroke& s, std::size_t corners);
// A triangle or quadrilateral refined from given corners (3 or 4, e.g. skeleton seeds).
std::optional<Fit> fit_polygon_from_corners(const PreparedStroke& s,
                                            const std::vector<PointD>& corners);
// From a quadrilateral fit: rectangle, square and diamond proposals.
std::vector<Fit> fit_rectangles(const PreparedStroke& s, const Fit& quadrilateral);
std::optional<Fit> fit_regular_polygon(const PreparedStroke& s, std::size_t sides, PointD center,
                                       double radius);
std::optional<Fit> fit_circle(const PreparedStroke& s);
std::optional<Fit> fit_arc(const PreparedStroke& s);
std::optional<Fit> fit_ellipse(const PreparedStroke& s);

} // namespace penshape::recognize_detail
