#include "stroke_figure.hpp"

#include <cmath>

#include "live_event_text.hpp"

namespace penshape::cli {
namespace {

PointD point(const v1::Point& p) { return {p.x(), p.y()}; }

Ring display_ring(const v1::Ring& ring) {
  Ring out;
  for (const auto& p : ring.points()) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) continue; // display only: skip junk
    out.push_back(exact(point(p)));
  }
  return out;
}

// The outline of the shape's parameters (none for a shape without vertices or a round part).
std::optional<render::ShapeOutline> params_outline(const v1::Shape& shape) {
  using Outline = render::ShapeOutline;
  switch (shape.params_case()) {
    case v1::Shape::kVertices: {
      const bool open =
          shape.kind() == v1::SHAPE_KIND_SEGMENT || shape.kind() == v1::SHAPE_KIND_POLYLINE;
      Outline out{.kind = open ? Outline::Kind::kPolyline : Outline::Kind::kPolygon};
      for (const auto& p : shape.vertices().vertices()) out.vertices.push_back(point(p));
      if (out.vertices.empty()) return std::nullopt;
      return out;
    }
    case v1::Shape::kCircle:
      return Outline::circle(point(shape.circle().center()), shape.circle().radius());
    case v1::Shape::kEllipse: {
      const auto& e = shape.ellipse();
      return Outline::ellipse(point(e.center()), e.semi_major(), e.semi_minor(), e.rotation_rad());
    }
    case v1::Shape::kArc: {
      const auto& a = shape.arc();
      return Outline::arc(point(a.center()), a.radius(), a.start_rad(), a.sweep_rad());
    }
    default:
      return std::nullopt;
  }
}

} // namespace

std::optional<render::ShapeOutline> shape_outline(const v1::Shape& shape) {
  auto out = params_outline(shape);
  if (out) out->label = shape_kind_name(shape.kind());
  return out;
}

PolygonSet display_polygon_set(const v1::PolygonSet& set) {
  PolygonSet out;
  for (const auto& poly : set.polygons()) {
    PolygonWithHoles p;
    p.outer = display_ring(poly.outer());
    if (p.outer.size() < 3) continue;
    for (const auto& hole : poly.holes()) {
      Ring h = display_ring(hole);
      if (h.size() >= 3) p.holes.push_back(std::move(h));
    }
    out.polygons.push_back(std::move(p));
  }
  return out;
}

render::StrokeFigure stroke_figure(const v1::StrokeFinished& finished, const v1::Shape* shape) {
  render::StrokeFigure figure;
  const v1::Stroke& stroke = finished.stroke();
  const double xr = stroke.tablet().x_resolution();
  const double yr = stroke.tablet().y_resolution();
  const bool in_mm = xr > 0 && yr > 0;
  for (const auto& s : stroke.samples()) {
    if (!s.tip()) continue;
    figure.samples.push_back(in_mm
                                 ? PointD{s.x() / xr, s.y() / yr}
                                 : PointD{static_cast<double>(s.x()), static_cast<double>(s.y())});
  }
  figure.caption = "stroke " + std::to_string(stroke.id()) + ", " +
                   std::to_string(stroke.samples_size()) + " samples";
  if (!in_mm) {
    figure.caption += " (device units: the tablet's resolution is unknown)";
    return figure;
  }
  figure.ink = display_polygon_set(finished.ink_polygon());
  if (shape != nullptr) {
    if (shape->has_certificate()) {
      const double r = shape->certificate().pen_radius().approx();
      const double eps = shape->certificate().tolerance().approx();
      if (std::isfinite(r) && r > 0) figure.pen_radius = r;
      if (std::isfinite(eps) && eps > 0) figure.tolerance = eps;
    }
    figure.shape = shape_outline(*shape);
    figure.caption += ": " + shape_kind_name(shape->kind());
    if (shape->has_certificate()) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " (H <= %.3g mm, eps = %.3g mm, r = %.3g mm)",
                    shape->certificate().hausdorff_bound().approx(), figure.tolerance,
                    figure.pen_radius);
      figure.caption += buf;
    }
  }
  if (!finished.not_analysed().empty()) figure.caption += " (not analysed)";
  return figure;
}

std::string stroke_file_name(const std::string& device_id, std::uint64_t stroke_id) {
  std::string safe;
  for (const char c : device_id) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '-' || c == '_';
    safe += ok ? c : '_';
  }
  if (safe.empty()) safe = "device";
  return "stroke-" + safe + "-" + std::to_string(stroke_id) + ".svg";
}

} // namespace penshape::cli
