#pragma once
// Pictures of penshape's results as SVG, drawn like the figures of the deconstruction paper:
// the input Q (blue outline), the solution P (green), offset(P, r) (grey, bounded by true
// circular arcs: SVG arc commands, no polygonal approximation) and the ε-band around it (cyan).
// For strokes: the samples (dots), the ink region, the snapped shape and the ε-band around the
// shape's ink.
//
// Every group has an id ("Q", "P", "offset", "band", "samples", "ink", "shape", "shape-ink") so
// tools and tests can find the layers. The SVG's coordinates are pixels: the model (any units,
// mm for strokes) is scaled uniformly so the drawing with its margin is `max_pixels` on its
// larger side (renderers work in 32-bit floats; huge model coordinates would lose precision).
// The caption sits in a strip above the drawing (the group "drawing" is translated below it).
//
// Limits: at most kMaxFigureVertices vertices in all (P, Q, samples, shape), else
// std::invalid_argument naming the count; non-finite coordinates or radii are
// std::invalid_argument too. Empty layers are simply left out.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape::render {

inline constexpr std::size_t kMaxFigureVertices = 2'000'000;

// A clean shape in model units (the recognizer's result, converted by the caller).
struct ShapeOutline {
  enum class Kind { kPolyline, kPolygon, kCircle, kEllipse, kArc };
  Kind kind = Kind::kPolygon;
  std::string label{};            // e.g. "square", shown in the figure's caption
  std::vector<PointD> vertices{}; // kPolyline (open) and kPolygon (closed, last != first)
  PointD center{};                // kCircle, kEllipse, kArc
  double radius = 0.0;            // kCircle, kArc
  double semi_major = 0.0;        // kEllipse
  double semi_minor = 0.0;        // kEllipse
  double rotation_rad = 0.0;      // kEllipse: major axis from +x
  double start_rad = 0.0;         // kArc: start angle from +x
  double sweep_rad = 0.0;         // kArc: signed sweep, |sweep| < 2 pi

  // The round outlines, each with the fields its kind reads (no label).
  static ShapeOutline circle(PointD c, double r) {
    return {.kind = Kind::kCircle, .center = c, .radius = r};
  }
  static ShapeOutline ellipse(PointD c, double a, double b, double rotation) {
    return {.kind = Kind::kEllipse,
            .center = c,
            .semi_major = a,
            .semi_minor = b,
            .rotation_rad = rotation};
  }
  static ShapeOutline arc(PointD c, double r, double start, double sweep) {
    return {.kind = Kind::kArc, .center = c, .radius = r, .start_rad = start, .sweep_rad = sweep};
  }
};

struct DeconstructionFigure {
  PolygonSet q;                // the input (required, non-empty)
  std::optional<PolygonSet> p; // the solution, when there is one
  double radius = 0.0;         // r >= 0
  double tolerance = 0.0;      // eps >= 0; 0 leaves the band out
  std::string caption;         // e.g. "YES  r = 2  eps = 1  (335 vertices)"
  bool y_up = true;            // model y axis points up (maps, the paper); false for tablets
  int max_pixels = 900;        // the larger side of the drawing, pixels (caption strip extra)
};

struct StrokeFigure {
  std::vector<PointD> samples; // the stroke's positions in mm, in time order
  // Several strokes in one figure (a group): indices into `samples` where a new stroke begins;
  // no ink joins the sample before a break to it.
  std::vector<std::size_t> stroke_starts;
  double pen_radius = 0.0; // r, mm: the ink is samples ⊕ D_r when `ink` is empty
  PolygonSet ink;          // the ink region Q as the daemon computed it (may be empty)
  std::optional<ShapeOutline> shape;
  double tolerance = 0.0; // eps, mm: band around the shape's ink (0 = no band)
  std::string caption;
  bool y_up = false;    // tablets: y grows downwards
  int max_pixels = 900; // the larger side of the drawing, pixels (caption strip extra)
};

// The figure of a deconstruction result: Q, and with YES the solution P, offset(P, r) and the
// ε-band; the caption states the answer, r, ε, δ, the engine and the vertex counts.
DeconstructionFigure deconstruction_figure(const PolygonSet& q, const DeconstructResult& result);

// The SVG document (UTF-8, standalone, SVG 1.1).
std::string deconstruction_svg(const DeconstructionFigure& figure);
std::string stroke_svg(const StrokeFigure& figure);

// Writes `svg` to `path` (replacing it); std::runtime_error naming the path on failure.
void write_svg_file(const std::string& path, const std::string& svg);

} // namespace penshape::render
