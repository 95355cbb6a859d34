// Clean shapes as SVG elements (see svg_writer.hpp). Coordinates go from the root's user units
// back into the element's own with the inverse of its transform chain (a similarity: readers skip
// other transforms), so circles stay circles.
#include "svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "clean_shape.hpp"
#include "svg_style.hpp"

namespace penshape::snap {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.8g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

std::string points_attr(const std::vector<PointD>& pts) {
  std::string out;
  for (const PointD& p : pts) {
    if (!out.empty()) out += ' ';
    out.append(num(p.x)).append(",").append(num(p.y));
  }
  return out;
}

bool geometry_attribute(const char* name) {
  static const char* const kDrop[] = {"d",
                                      "points",
                                      "x1",
                                      "y1",
                                      "x2",
                                      "y2",
                                      "inkscape:original-d",
                                      "inkscape:path-effect",
                                      "inkscape:connector-curvature"};
  for (const char* d : kDrop) {
    if (std::strcmp(name, d) == 0) return true;
  }
  return std::strncmp(name, "sodipodi:", 9) == 0;
}

// Angle of a direction after the map, radians.
double mapped_angle(const Affine& m, double angle) {
  const PointD o = m.apply({0, 0}), u = m.apply({std::cos(angle), std::sin(angle)});
  return std::atan2(u.y - o.y, u.x - o.x);
}

bool multiple_of_half_pi(double a) {
  const double k = std::round(a / (std::numbers::pi / 2));
  return std::abs(a - k * std::numbers::pi / 2) < 1e-9;
}

struct Element {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> attrs;
};

Element polygon_or_rect(const std::vector<PointD>& v, bool rect_like) {
  if (rect_like && v.size() == 4) {
    const bool aligned = (std::abs(v[0].x - v[1].x) < 1e-9 * (1 + std::abs(v[0].x)) ||
                          std::abs(v[0].y - v[1].y) < 1e-9 * (1 + std::abs(v[0].y)));
    if (aligned) {
      double x0 = v[0].x, x1 = v[0].x, y0 = v[0].y, y1 = v[0].y;
      for (const PointD& p : v) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y),
        y1 = std::max(y1, p.y);
      }
      return {"rect",
              {{"x", num(x0)}, {"y", num(y0)}, {"width", num(x1 - x0)}, {"height", num(y1 - y0)}}};
    }
  }
  return {"polygon", {{"points", points_attr(v)}}};
}

// An ellipse of semi-axes a (along `angle`) and b, as an element in local coordinates.
Element ellipse_element(PointD c, double a, double b, double angle) {
  if (multiple_of_half_pi(angle)) {
    const bool swap = std::abs(std::sin(angle)) > 0.5;
    return {
        "ellipse",
        {{"cx", num(c.x)}, {"cy", num(c.y)}, {"rx", num(swap ? b : a)}, {"ry", num(swap ? a : b)}}};
  }
  const PointD u{std::cos(angle), std::sin(angle)};
  const std::string p0 = num(c.x + a * u.x) + "," + num(c.y + a * u.y);
  const std::string p1 = num(c.x - a * u.x) + "," + num(c.y - a * u.y);
  const std::string arc =
      "A " + num(a) + "," + num(b) + " " + num(angle * 180 / std::numbers::pi) + " 0 1 ";
  return {"path", {{"d", "M " + p0 + " " + arc + p1 + " " + arc + p0 + " Z"}}};
}

Element arc_element(const Recognition& r, const Affine& to_local) {
  const ShapeParams& p = r.params;
  const auto at = [&](double t) {
    return to_local.apply(
        {p.center.x + p.radius_x * std::cos(t), p.center.y + p.radius_x * std::sin(t)});
  };
  const PointD s = at(p.start_angle), m = at(p.start_angle + p.sweep_angle / 2);
  const PointD e = at(p.start_angle + p.sweep_angle);
  // Sweep flag 1 is the direction of increasing angle: start, middle, end turn counterclockwise
  // in the (x, y) frame, whichever way y points on screen.
  const double cross = (m.x - s.x) * (e.y - s.y) - (m.y - s.y) * (e.x - s.x);
  const double radius = p.radius_x * to_local.scale();
  const bool large = std::abs(p.sweep_angle) > std::numbers::pi;
  return {"path",
          {{"d", "M " + num(s.x) + "," + num(s.y) + " A " + num(radius) + "," + num(radius) +
                     " 0 " + (large ? "1" : "0") + " " + (cross > 0 ? "1" : "0") + " " + num(e.x) +
                     "," + num(e.y)}}};
}

// An arrow as one path: a subpath per piece (shaft through its bends, head, tail head), or all of
// it end to start.
Element arrow_element(const Recognition& r, const Affine& to_local, bool backwards) {
  std::vector<std::vector<PointD>> pieces = arrow_pieces(r);
  if (backwards) {
    std::reverse(pieces.begin(), pieces.end());
    for (std::vector<PointD>& piece : pieces) std::reverse(piece.begin(), piece.end());
  }
  std::string d;
  for (const std::vector<PointD>& piece : pieces) {
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const PointD q = to_local.apply(piece[i]);
      if (!d.empty()) d += ' ';
      d.append(i == 0 ? "M " : "L ").append(num(q.x)).append(",").append(num(q.y));
    }
  }
  return {"path", {{"d", d}}};
}

Element shape_element(const Recognition& r, const Affine& to_local, bool backwards) {
  const ShapeParams& p = r.params;
  std::vector<PointD> v;
  for (const PointD& q : p.vertices) v.push_back(to_local.apply(q));
  const double s = to_local.scale();
  switch (r.shape) {
    case ShapeClass::kSegment:
      return {"line",
              {{"x1", num(v[0].x)}, {"y1", num(v[0].y)}, {"x2", num(v[1].x)}, {"y2", num(v[1].y)}}};
    case ShapeClass::kPolyline:
      return {"polyline", {{"points", points_attr(v)}}};
    case ShapeClass::kRectangle:
    case ShapeClass::kSquare:
      return polygon_or_rect(v, true);
    case ShapeClass::kCircle: {
      const PointD c = to_local.apply(p.center);
      return {"circle", {{"cx", num(c.x)}, {"cy", num(c.y)}, {"r", num(p.radius_x * s)}}};
    }
    case ShapeClass::kEllipse:
      return ellipse_element(to_local.apply(p.center), p.radius_x * s, p.radius_y * s,
                             mapped_angle(to_local, p.rotation));
    case ShapeClass::kArc:
      return arc_element(r, to_local);
    case ShapeClass::kArrow:
    case ShapeClass::kDoubleArrow:
      return arrow_element(r, to_local, backwards);
    default:
      return polygon_or_rect(v, false);
  }
}

std::string certificate_text(const Certificate& c) {
  return "method=" + c.method + " bound=" + num(c.bound) + " epsilon=" + num(c.epsilon) +
         " pen_radius=" + num(c.pen_radius);
}

// A calligraphy outline's fill becomes the clean shape's stroke.
std::string stroked_style(const pugi::xml_node& old, double local_width) {
  const PaintStyle computed = computed_style(old, computed_style(old.parent(), PaintStyle{}));
  auto decl = parse_style(old.attribute("style").value());
  std::erase_if(decl, [](const auto& kv) {
    return kv.first == "fill" || kv.first == "stroke" || kv.first == "stroke-width" ||
           kv.first == "fill-opacity" || kv.first == "stroke-opacity" ||
           kv.first == "stroke-linecap" || kv.first == "stroke-linejoin";
  });
  decl.emplace_back("fill", "none");
  decl.emplace_back("stroke", computed.fill);
  decl.emplace_back("stroke-opacity", computed.fill_opacity);
  decl.emplace_back("stroke-width", num(local_width));
  decl.emplace_back("stroke-linecap", "round");
  decl.emplace_back("stroke-linejoin", "round");
  return format_style(decl);
}

} // namespace

pugi::xml_node replace_svg_stroke(const SvgStroke& stroke, const Recognition& r, double pen_radius,
                                  bool backwards) {
  const pugi::xml_node old = stroke.element;
  // The element's coordinates are its parent's after its own transform: to_root includes it.
  const Affine to_local = stroke.to_root.inverse();
  const Element e = shape_element(r, to_local, backwards);
  pugi::xml_node parent = old.parent();
  pugi::xml_node out = parent.insert_child_before(e.tag.c_str(), old);
  for (const pugi::xml_attribute& a : old.attributes()) {
    if (geometry_attribute(a.name())) continue;
    if (stroke.calligraphy &&
        (std::strcmp(a.name(), "fill") == 0 || std::strcmp(a.name(), "stroke") == 0 ||
         std::strcmp(a.name(), "style") == 0)) {
      continue;
    }
    out.append_attribute(a.name()) = a.value();
  }
  if (stroke.calligraphy) {
    out.append_attribute("style") = stroked_style(old, 2 * pen_radius * to_local.scale()).c_str();
  }
  for (const auto& [k, v] : e.attrs) out.append_attribute(k.c_str()) = v.c_str();
  out.append_attribute("data-penshape-class") = to_string(r.shape);
  out.append_attribute("data-penshape-certificate") = certificate_text(r.certificate).c_str();
  parent.remove_child(old);
  return out;
}

} // namespace penshape::snap
