#pragma once
// The fitters: each proposes the best shape of its family for a prepared stroke (or nothing when
// the family does not apply). Fits are estimates; only the certificate decides a snap.
#include <cmath>
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
Refinement refine_minimax(const PreparedStroke& stroke, const std::vector<double>& params,
                          const ShapeBuilder& build, double initial_step, bool use_key_points);
// The refinement objective for one shape.
double fit_objective(const PreparedStroke& stroke, const CleanShape& shape, bool use_key_points);
// The same objective, evaluated for many shapes of one search: each point's scan for its nearest
// segment starts where the previous shape's stopped, and stops once the point cannot raise the
// objective, so the value is fit_objective's bit for bit, at a fraction of the work. A search
// that keeps a shape only when it beats its best passes that best as `stop_at`: the evaluation
// stops once the value reaches it (returning a value >= stop_at), starting with the point that
// raised the last shape's value (the one most likely to rule the next trial out).
class FitObjective {
 public:
  FitObjective(const PreparedStroke& stroke, bool use_key_points);
  double operator()(const CleanShape& shape, double stop_at = INFINITY);

 private:
  // A run of consecutive stroke segments, with its bounding box and longest segment: a key point
  // far from the box (with room for rounding) has no segment of it nearer than the best so far.
  struct Block {
    std::size_t first = 0, end = 0; // segments [first, end)
    PointD lo, hi;
    double longest = 0.0;
  };
  double raise_to_stroke_distance(PointD v, double worst, std::size_t& hint) const;

  const PreparedStroke& stroke_;
  bool use_key_points_;
  std::size_t fit_hint_ = 0;           // the segment of the shape nearest the last fit point
  std::size_t raised_at_ = 0;          // the fit point that set the last value (tried first)
  std::size_t raised_hint_ = 0;        // the segment of the shape nearest that point
  std::vector<std::size_t> key_hints_; // per key point, the stroke segment nearest it
  std::vector<Block> blocks_;          // over stroke_.points (key points only)
};
// max(worst, the largest polyline_distance from `points` to `path`), exactly: each point's scan
// starts at segment `hint` (updated to its nearest one) and stops once the point is proven no
// farther than the maximum so far. The run stops once the maximum reaches `stop_at` (the value
// returned is then >= stop_at); `raised_at`, when given, is set to the index of the point that
// raised the value last.
double raise_to_polyline_distance(std::span<const PointD> points, std::span<const PointD> path,
                                  double worst, std::size_t& hint, double stop_at = INFINITY,
                                  std::size_t* raised_at = nullptr);

// Corner search by dynamic programming on the fit points: indices of k vertices minimising the
// summed squared distance of the points to the chords. Open: the first and last points are
// vertices (k >= 2). Closed: the fit points are a cycle (k >= 3).
std::vector<std::size_t> open_corners(const std::vector<PointD>& pts, std::size_t k);
// Closed, for every k from 3 to `most` at once (index k; empty where the points are too few).
std::vector<std::vector<std::size_t>> closed_corner_chains(const std::vector<PointD>& pts,
                                                           std::size_t most);
// The closed chain of k corners of s's fit points, from chains made on first use (every count up
// to kMaxPolygonCorners in one search: a stroke is fitted with several).
const std::vector<std::size_t>& closed_corners(const PreparedStroke& s, std::size_t k);

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
// A closed polygon refined from given corners (at least 3: skeleton seeds, the stroke's sharp
// turns).
std::optional<Fit> fit_polygon_from_corners(const PreparedStroke& s,
                                            const std::vector<PointD>& corners);
// Closed polygons from corners where the hand turned (in the stroke's order), not refined, so
// their corners stay at the turns (a minimax refinement trades a turn for a lump's distance):
// at_turns has its vertices at the corners themselves; through_turns has as sides the lines
// fitted to the stroke between them, met where the hand turned (nothing when the corners are not
// in the stroke's order).
std::optional<Fit> fit_polygon_at_turns(const PreparedStroke& s,
                                        const std::vector<PointD>& corners);
std::optional<Fit> fit_polygon_through_turns(const PreparedStroke& s,
                                             const std::vector<PointD>& corners);
// Corners at the closed stroke's k sharpest turns (turn_corners.cpp), read between chords 1/32 of
// its length either way, at least two windows apart; empty unless each turns by at least
// `least_turn` (radians) and twice the stroke's median turn.
std::vector<PointD> sharp_turn_corners(const PreparedStroke& s, std::size_t k, double least_turn);
// How many places (at most `at_most`) the stroke turns by at least `least_turn` (radians), read as
// sharp_turn_corners reads them, with no median test (a star's median turn is a corner's).
std::size_t sharp_turn_count(const PreparedStroke& s, std::size_t at_most, double least_turn);
// From a quadrilateral fit: rectangle, square and diamond proposals.
std::vector<Fit> fit_rectangles(const PreparedStroke& s, const Fit& quadrilateral);
std::optional<Fit> fit_regular_polygon(const PreparedStroke& s, std::size_t sides, PointD center,
                                       double radius);
std::optional<Fit> fit_circle(const PreparedStroke& s);
std::optional<Fit> fit_arc(const PreparedStroke& s);
std::optional<Fit> fit_ellipse(const PreparedStroke& s);

} // namespace penshape::recognize_detail
