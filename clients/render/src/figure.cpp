// SVG figures of deconstructions and strokes. Regions swept by a disk are drawn as unions of
// exact pieces (stadiums, annuli, arc bands): each piece is stroked with twice the outline width
// and then filled inside one group, so the fills hide every inner outline and only the union's
// boundary stays visible, with no polygonal approximation of the arcs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "penshape/render/figure.hpp"
#include "penshape/types/lookup_table.hpp"
#include "svg_paths.hpp"

namespace penshape::render {
namespace {

using detail::num;
using detail::PathBuilder;

// Segments to sweep (a == b for a single point), circles to turn into annuli, arcs to band.
struct Skeleton {
  struct Segment {
    PointD a, b;
  };
  struct Circle {
    PointD center;
    double radius;
  };
  struct Arc {
    PointD center;
    double radius, start, sweep; // screen angles
  };
  std::vector<Segment> segments;
  std::vector<Circle> circles;
  std::vector<Arc> arcs;
  std::vector<std::vector<PointD>> filled_rings; // P's own area (evenodd), part of its offset
};

class Bounds {
 public:
  void add(PointD p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw std::invalid_argument("figure: a coordinate is not finite");
    }
    min_x = std::min(min_x, p.x);
    min_y = std::min(min_y, p.y);
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
    ++count;
  }
  double min_x = std::numeric_limits<double>::infinity();
  double min_y = std::numeric_limits<double>::infinity();
  double max_x = -std::numeric_limits<double>::infinity();
  double max_y = -std::numeric_limits<double>::infinity();
  std::size_t count = 0;
};

// Model → screen: a translation, a reflection of y when the model's y axis points up, and a
// uniform scale to pixels. SVG renderers work in 32-bit floats and lay out text in fixed point,
// so coordinates stay in pixel range whatever the model's units (maps in 1e8 units included).
struct View {
  Bounds box;
  double margin = 0.0; // model units
  bool y_up = true;
  double scale = 1.0; // pixels per model unit
  [[nodiscard]] PointD map(PointD p) const {
    return {(p.x - box.min_x + margin) * scale,
            (y_up ? box.max_y - p.y + margin : p.y - box.min_y + margin) * scale};
  }
  [[nodiscard]] double len(double model_length) const { return model_length * scale; }
  [[nodiscard]] double angle(double model_angle) const { return y_up ? -model_angle : model_angle; }
  [[nodiscard]] double width() const { return (box.max_x - box.min_x + 2 * margin) * scale; }
  [[nodiscard]] double height() const { return (box.max_y - box.min_y + 2 * margin) * scale; }
  [[nodiscard]] double size() const { return std::max(width(), height()); }
};

void check_radius(double v, const char* what) {
  if (!std::isfinite(v) || v < 0) {
    throw std::invalid_argument(std::string("figure: ") + what + " must be finite and >= 0");
  }
}

std::string escape(const std::string& text) {
  static constexpr LookupTable<char, std::string_view, 4> kEntities{
      {{'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}}};
  std::string out;
  for (const char c : text) {
    if (const std::string_view entity = lookup_or(kEntities, c, {}); !entity.empty()) {
      out += entity;
    } else {
      out += c;
    }
  }
  return out;
}

std::vector<PointD> display_ring(const Ring& ring) {
  std::vector<PointD> out;
  out.reserve(ring.size());
  for (const auto& p : ring) out.push_back(to_double(p));
  return out;
}

void add_polygon_set(Bounds& box, const PolygonSet& set) {
  for (const auto& poly : set.polygons) {
    for (const auto& p : poly.outer) box.add(to_double(p));
  }
}

// Ellipse center lines are not circular arcs; they are swept as fine polylines.
constexpr int kEllipseSegments = 128;

std::vector<PointD> ellipse_points(const ShapeOutline& s) {
  std::vector<PointD> out;
  const double c = std::cos(s.rotation_rad);
  const double sn = std::sin(s.rotation_rad);
  for (int i = 0; i < kEllipseSegments; ++i) {
    const double t = 2 * std::numbers::pi * i / kEllipseSegments;
    const double x = s.semi_major * std::cos(t);
    const double y = s.semi_minor * std::sin(t);
    out.push_back({s.center.x + c * x - sn * y, s.center.y + sn * x + c * y});
  }
  return out;
}

void add_shape_bounds(Bounds& box, const ShapeOutline& s) {
  switch (s.kind) {
    case ShapeOutline::Kind::kPolyline:
    case ShapeOutline::Kind::kPolygon:
      for (const auto& p : s.vertices) box.add(p);
      break;
    case ShapeOutline::Kind::kCircle:
    case ShapeOutline::Kind::kArc:
      check_radius(s.radius, "shape radius");
      box.add({s.center.x - s.radius, s.center.y - s.radius});
      box.add({s.center.x + s.radius, s.center.y + s.radius});
      break;
    case ShapeOutline::Kind::kEllipse:
      check_radius(s.semi_major, "ellipse semi-major axis");
      check_radius(s.semi_minor, "ellipse semi-minor axis");
      for (const auto& p : ellipse_points(s)) box.add(p);
      break;
  }
}

void add_closed_chain(Skeleton& sk, const std::vector<PointD>& pts) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    sk.segments.push_back({pts[i], pts[(i + 1) % pts.size()]});
  }
}

Skeleton polygon_set_skeleton(const View& view, const PolygonSet& set) {
  Skeleton sk;
  for (const auto& poly : set.polygons) {
    std::vector<std::vector<PointD>> rings{display_ring(poly.outer)};
    for (const auto& hole : poly.holes) rings.push_back(display_ring(hole));
    for (auto& r : rings) {
      for (auto& p : r) p = view.map(p);
      add_closed_chain(sk, r);
      sk.filled_rings.push_back(std::move(r));
    }
  }
  return sk;
}

Skeleton shape_skeleton(const View& view, const ShapeOutline& s) {
  Skeleton sk;
  std::vector<PointD> pts;
  switch (s.kind) {
    case ShapeOutline::Kind::kPolyline:
      for (const auto& p : s.vertices) pts.push_back(view.map(p));
      if (pts.size() == 1) sk.segments.push_back({pts[0], pts[0]});
      for (std::size_t i = 0; i + 1 < pts.size(); ++i) sk.segments.push_back({pts[i], pts[i + 1]});
      break;
    case ShapeOutline::Kind::kPolygon:
      for (const auto& p : s.vertices) pts.push_back(view.map(p));
      add_closed_chain(sk, pts);
      break;
    case ShapeOutline::Kind::kEllipse:
      for (const auto& p : ellipse_points(s)) pts.push_back(view.map(p));
      add_closed_chain(sk, pts);
      break;
    case ShapeOutline::Kind::kCircle:
      sk.circles.push_back({view.map(s.center), view.len(s.radius)});
      break;
    case ShapeOutline::Kind::kArc:
      sk.arcs.push_back({view.map(s.center), view.len(s.radius), view.angle(s.start_rad),
                         view.angle(s.sweep_rad)});
      break;
  }
  return sk;
}

struct Piece {
  std::string d;
  bool evenodd = false;
};

// The region skeleton ⊕ D_width as separate path elements (their union is the region).
// `with_area`: P's own area belongs to offset(P, width); a shape's center line has none.
std::vector<Piece> swept_pieces(const Skeleton& sk, double width, bool with_area) {
  std::vector<Piece> out;
  if (with_area && !sk.filled_rings.empty()) {
    PathBuilder area;
    for (const auto& r : sk.filled_rings) detail::ring(area, r);
    out.push_back({area.str(), true});
  }
  if (width <= 0) return out;
  for (const auto& seg : sk.segments) {
    PathBuilder p;
    detail::capsule(p, seg.a, seg.b, width);
    out.push_back({p.str()});
  }
  for (const auto& c : sk.circles) {
    PathBuilder p;
    p.circle(c.center, c.radius + width, true);
    if (c.radius > width) p.circle(c.center, c.radius - width, false);
    out.push_back({p.str()});
  }
  for (const auto& a : sk.arcs) {
    PathBuilder p;
    detail::arc_band(p, a.center, a.radius, a.start, a.sweep, width);
    out.push_back({p.str()});
  }
  return out;
}

void paths(std::string& svg, const std::vector<Piece>& pieces) {
  for (const auto& piece : pieces) {
    svg += "<path d=\"" + piece.d + (piece.evenodd ? "\" fill-rule=\"evenodd\"/>\n" : "\"/>\n");
  }
}

// A union of pieces, translucent, with its boundary outlined.
void union_group(std::string& svg, const std::string& id, const std::vector<Piece>& pieces,
                 const std::string& fill, const std::string& outline, double line_width,
                 double opacity, const std::string& mask = "") {
  if (pieces.empty()) return;
  svg += "<g id=\"" + id + "\" opacity=\"" + num(opacity) + "\"";
  if (!mask.empty()) svg += " mask=\"url(#" + mask + ")\"";
  svg += ">\n";
  if (!outline.empty()) {
    svg += "<g fill=\"none\" stroke=\"" + outline + "\" stroke-width=\"" + num(2 * line_width) +
           "\" stroke-linejoin=\"round\">\n";
    paths(svg, pieces);
    svg += "</g>\n";
  }
  svg += "<g fill=\"" + fill + "\" stroke=\"none\">\n";
  paths(svg, pieces);
  svg += "</g>\n</g>\n";
}

// The band {x : r - eps <= dist(x, skeleton) <= r + eps}: the outer sweep with the inner sweep
// masked out.
void band_group(std::string& svg, const View& view, const Skeleton& sk, double r, double eps,
                bool with_area) {
  if (eps <= 0) return;
  const std::vector<Piece> outer = swept_pieces(sk, r + eps, with_area);
  const bool has_inner = r > eps;
  if (has_inner) {
    svg += "<mask id=\"band-hole\" maskUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"" +
           num(view.width()) + "\" height=\"" + num(view.height()) + "\">\n";
    svg += "<rect x=\"0\" y=\"0\" width=\"" + num(view.width()) + "\" height=\"" +
           num(view.height()) + "\" fill=\"white\"/>\n<g fill=\"black\">\n";
    paths(svg, swept_pieces(sk, r - eps, with_area));
    svg += "</g>\n</mask>\n";
  }
  union_group(svg, "band", outer, "#00c8d7", "", 0, 0.3, has_inner ? "band-hole" : "");
}

void polygon_outline(std::string& svg, const std::string& id, const View& view,
                     const PolygonSet& set, const std::string& fill, double fill_opacity,
                     const std::string& color, double line_width) {
  PathBuilder p;
  for (const auto& poly : set.polygons) {
    auto outer = display_ring(poly.outer);
    for (auto& q : outer) q = view.map(q);
    detail::ring(p, outer);
    for (const auto& hole : poly.holes) {
      auto h = display_ring(hole);
      for (auto& q : h) q = view.map(q);
      detail::ring(p, h);
    }
  }
  if (p.empty()) return;
  svg += "<g id=\"" + id + "\"><path d=\"" + p.str() + "\" fill=\"" + fill + "\" fill-opacity=\"" +
         num(fill_opacity) + "\" fill-rule=\"evenodd\" stroke=\"" + color + "\" stroke-width=\"" +
         num(line_width) + "\" stroke-linejoin=\"round\"/></g>\n";
}

void shape_center_line(std::string& svg, const View& view, const ShapeOutline& s,
                       double line_width) {
  PathBuilder p;
  std::vector<PointD> pts;
  switch (s.kind) {
    case ShapeOutline::Kind::kPolyline:
      for (const auto& v : s.vertices) pts.push_back(view.map(v));
      if (!pts.empty()) p.move_to(pts[0]);
      for (std::size_t i = 1; i < pts.size(); ++i) p.line_to(pts[i]);
      break;
    case ShapeOutline::Kind::kPolygon:
      for (const auto& v : s.vertices) pts.push_back(view.map(v));
      detail::ring(p, pts);
      break;
    case ShapeOutline::Kind::kEllipse:
      for (const auto& v : ellipse_points(s)) pts.push_back(view.map(v));
      detail::ring(p, pts);
      break;
    case ShapeOutline::Kind::kCircle:
      p.circle(view.map(s.center), view.len(s.radius), true);
      break;
    case ShapeOutline::Kind::kArc:
      detail::arc_line(p, view.map(s.center), view.len(s.radius), view.angle(s.start_rad),
                       view.angle(s.sweep_rad));
      break;
  }
  if (p.empty()) return;
  svg += "<g id=\"shape\"><path d=\"" + p.str() +
         "\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"" + num(line_width) +
         "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"/></g>\n";
}

View make_view(Bounds box, double pad, bool y_up, int max_pixels) {
  if (box.count == 0) box.add({0, 0});
  View view;
  view.box = box;
  view.y_up = y_up;
  const double extent = std::max(box.max_x - box.min_x, box.max_y - box.min_y);
  view.margin = pad + std::max(extent * 0.05, 1e-6);
  view.scale = std::max(1, max_pixels) / view.size(); // size() at scale 1: model units
  return view;
}

// The caption gets a strip of its own above the drawing, so it never covers the geometry.
double caption_height(const View& view, const std::string& caption) {
  return caption.empty() ? 0.0 : std::max(16.0, view.size() * 0.04);
}

std::string open_svg(const View& view, const std::string& caption) {
  const double strip = caption_height(view, caption);
  const double height = view.height() + strip;
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
         num(std::ceil(view.width())) + "\" height=\"" + num(std::ceil(height)) +
         "\" viewBox=\"0 0 " + num(view.width()) + " " + num(height) + "\">\n";
  svg += "<title>" + escape(caption) + "</title>\n";
  svg += "<rect id=\"background\" x=\"0\" y=\"0\" width=\"" + num(view.width()) + "\" height=\"" +
         num(height) + "\" fill=\"white\"/>\n";
  if (!caption.empty()) {
    const double font = strip * 0.6;
    svg += "<text id=\"caption\" x=\"" + num(font * 0.5) + "\" y=\"" + num(strip * 0.75) +
           "\" font-family=\"sans-serif\" font-size=\"" + num(font) + "\" fill=\"#222\">" +
           escape(caption) + "</text>\n";
  }
  svg += "<g id=\"drawing\" transform=\"translate(0 " + num(strip) + ")\">\n";
  return svg;
}

// A figure's view, with the pen radius, the tolerance and the line width in picture units.
struct ScaledView {
  View view;
  double r = 0.0;
  double eps = 0.0;
  double lw = 0.0;
};

ScaledView scaled_view(const Bounds& box, double radius, double tolerance, bool y_up,
                       int max_pixels) {
  const View view = make_view(box, radius + tolerance, y_up, max_pixels);
  return {view, view.len(radius), view.len(tolerance), view.size() * 0.002};
}

void close_svg(std::string& svg) { svg += "</g>\n</svg>\n"; }

void check_size(std::size_t vertices) {
  if (vertices > kMaxFigureVertices) {
    throw std::invalid_argument("figure: " + std::to_string(vertices) +
                                " vertices exceed the limit of " +
                                std::to_string(kMaxFigureVertices));
  }
}

} // namespace

std::string deconstruction_svg(const DeconstructionFigure& f) {
  check_radius(f.radius, "radius");
  check_radius(f.tolerance, "tolerance");
  if (f.q.empty()) throw std::invalid_argument("figure: the input Q is empty");
  check_size(f.q.vertex_count() + (f.p ? f.p->vertex_count() : 0));
  Bounds box;
  add_polygon_set(box, f.q);
  if (f.p) add_polygon_set(box, *f.p);
  const auto [view, r, eps, lw] = scaled_view(box, f.radius, f.tolerance, f.y_up, f.max_pixels);

  std::string svg = open_svg(view, f.caption);
  if (f.p && !f.p->empty()) {
    const Skeleton sk = polygon_set_skeleton(view, *f.p);
    band_group(svg, view, sk, r, eps, true);
    union_group(svg, "offset", swept_pieces(sk, r, true), "#9a9a9a", "#1f3f8f", lw, 0.45);
  }
  polygon_outline(svg, "Q", view, f.q, "#1f77b4", 0.08, "#1f77b4", 2 * lw);
  if (f.p && !f.p->empty()) polygon_outline(svg, "P", view, *f.p, "#2ca02c", 0.35, "#2ca02c", lw);
  close_svg(svg);
  return svg;
}

std::string stroke_svg(const StrokeFigure& f) {
  check_radius(f.pen_radius, "pen radius");
  check_radius(f.tolerance, "tolerance");
  check_size(f.samples.size() + f.ink.vertex_count() + (f.shape ? f.shape->vertices.size() : 0));
  Bounds box;
  for (const auto& p : f.samples) box.add(p);
  add_polygon_set(box, f.ink);
  if (f.shape) add_shape_bounds(box, *f.shape);
  const auto [view, r, eps, lw] = scaled_view(box, f.pen_radius, f.tolerance, f.y_up, f.max_pixels);

  std::string svg = open_svg(view, f.caption);
  // The ink: the daemon's polygon Q when given, else the samples swept by the pen disk.
  if (!f.ink.empty()) {
    polygon_outline(svg, "ink", view, f.ink, "#7b4fa0", 0.25, "#7b4fa0", lw);
  } else if (!f.samples.empty() && f.pen_radius > 0) {
    Skeleton sk;
    for (std::size_t i = 0; i < f.samples.size(); ++i) {
      const PointD a = view.map(f.samples[i]);
      const bool last =
          i + 1 >= f.samples.size() ||
          std::find(f.stroke_starts.begin(), f.stroke_starts.end(), i + 1) != f.stroke_starts.end();
      const PointD b = view.map(f.samples[last ? i : i + 1]);
      sk.segments.push_back({a, b});
    }
    union_group(svg, "ink", swept_pieces(sk, r, false), "#7b4fa0", "#7b4fa0", lw, 0.3);
  }
  if (f.shape) {
    const Skeleton sk = shape_skeleton(view, *f.shape);
    band_group(svg, view, sk, r, eps, false);
    union_group(svg, "shape-ink", swept_pieces(sk, r, false), "#9a9a9a", "#444444", lw * 0.5, 0.35);
    shape_center_line(svg, view, *f.shape, 2 * lw);
  }
  if (!f.samples.empty()) {
    const double dot = std::max(r * 0.12, view.size() * 0.0015);
    svg += "<g id=\"samples\" fill=\"#111\">\n";
    for (const auto& s : f.samples) {
      const PointD p = view.map(s);
      svg += "<circle cx=\"" + num(p.x) + "\" cy=\"" + num(p.y) + "\" r=\"" + num(dot) + "\"/>\n";
    }
    svg += "</g>\n";
  }
  close_svg(svg);
  return svg;
}

DeconstructionFigure deconstruction_figure(const PolygonSet& q, const DeconstructResult& result) {
  DeconstructionFigure f;
  f.q = q;
  f.radius = to_double(result.params.radius);
  f.tolerance = to_double(result.params.tolerance);
  if (result.answer == Answer::kYes) f.p = result.solution;
  char buf[192];
  std::snprintf(buf, sizeof buf, "%s  r = %.6g  eps = %.6g  delta = %.6g  (%s engine)  |Q| = %zu",
                to_string(result.answer), f.radius, f.tolerance, to_double(result.params.precision),
                to_string(result.engine), q.vertex_count());
  f.caption = buf;
  if (f.p) f.caption += "  |P| = " + std::to_string(f.p->vertex_count());
  return f;
}

void write_svg_file(const std::string& path, const std::string& svg) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << svg;
  out.close();
  if (!out) throw std::runtime_error("error while writing " + path);
}

} // namespace penshape::render
