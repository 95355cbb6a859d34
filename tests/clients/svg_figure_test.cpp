// The SVG figures: valid XML with the expected layers, arcs where the geometry has arcs, and
// the geometry checked against numbers computed here (edge lengths, radii, the y reflection).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include "dollar_stroke.hpp"
#include "penshape/render/figure.hpp"
#include "svg_xml.hpp"

namespace penshape::testing {
namespace {

using render::DeconstructionFigure;
using render::ShapeOutline;
using render::StrokeFigure;

// A generated polygon (tests/support/gen) read from its x-y text.
PolygonSet read_polygon(const std::string& text) {
  std::istringstream in(text);
  PolygonSet set;
  set.polygons.emplace_back();
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream xy(line);
    double x = 0, y = 0;
    xy >> x >> y;
    set.polygons.back().outer.push_back(exact(PointD{x, y}));
  }
  return set;
}

PolygonSet polygon(std::initializer_list<PointD> points) {
  PolygonSet set;
  set.polygons.emplace_back();
  for (const auto& p : points) set.polygons.back().outer.push_back(exact(p));
  return set;
}

double dist(const std::vector<double>& a, std::size_t i, const std::vector<double>& b,
            std::size_t j) {
  return std::hypot(a[i] - b[j], a[i + 1] - b[j + 1]);
}

// The end point of a path command (the last two numbers).
std::vector<double> end_point(const PathCommand& c) {
  return {c.args[c.args.size() - 2], c.args[c.args.size() - 1]};
}

TEST(SvgFigure, DeconstructionHasTheLayersOfThePaperFigures) {
  DeconstructionFigure f;
  f.q = read_polygon(gen::spikes(3, 20, 60.0, 100.0).text);
  const double r = 4e6;
  f.radius = r;
  f.tolerance = 1e6;
  // A triangle inside the wheel as the "solution" to draw (the figure does not judge it).
  f.p = polygon({{-3e7, -2e7}, {3e7, -2e7}, {0, 3e7}});
  f.caption = "YES r=4e6 eps=1e6 <test> & more";
  const std::string svg = render::deconstruction_svg(f);
  const ptree doc = parse_xml(svg);
  const ptree& root = doc.get_child("svg");
  for (const char* id : {"Q", "P", "offset", "band", "band-hole", "caption", "background"}) {
    EXPECT_NE(find_by_id(root, id), nullptr) << id;
  }
  EXPECT_EQ(root.get<std::string>("title"), f.caption);

  // Q: one ring, all 40 vertices of the file.
  const auto q_cmds = parse_path(*attribute(*elements(*find_by_id(root, "Q"), "path")[0], "d"));
  ASSERT_EQ(q_cmds.size(), 41U); // M, 39 L, Z
  EXPECT_EQ(q_cmds[0].op, 'M');
  EXPECT_EQ(q_cmds[40].op, 'Z');

  // The y axis is reflected (y_up): the wheel's highest vertex is drawn highest (smallest y).
  std::size_t top_model = 0;
  for (std::size_t i = 0; i < f.q.polygons[0].outer.size(); ++i) {
    if (f.q.polygons[0].outer[i].y > f.q.polygons[0].outer[top_model].y) top_model = i;
  }
  std::size_t top_svg = 0;
  for (std::size_t i = 0; i < 40; ++i) {
    if (q_cmds[i].args[1] < q_cmds[top_svg].args[1]) top_svg = i;
  }
  EXPECT_EQ(top_svg, top_model);

  // offset(P, r): P's area plus one stadium per edge, drawn twice (outline pass, fill pass).
  const ptree* offset = find_by_id(root, "offset");
  const auto pieces = elements(*offset, "path");
  ASSERT_EQ(pieces.size(), 2U * (1 + 3));
  // The SVG is in pixels: the model is scaled uniformly. The scale, from the first stadium's
  // width (2r), must fit the picture: the drawing's larger side is max_pixels.
  const auto first = parse_path(*attribute(*pieces[1], "d"));
  ASSERT_EQ(first.size(), 8U);
  const double s = dist(end_point(first[1]), 0, end_point(first[3]), 0) / (2 * r);
  const auto& p_ring = f.p->polygons[0].outer;
  for (std::size_t e = 0; e < 3; ++e) {
    const auto cmds = parse_path(*attribute(*pieces[1 + e], "d"));
    // M, L, A, A, L, A, A, Z: two straight sides and two round caps of radius r.
    ASSERT_EQ(cmds.size(), 8U) << e;
    const PointD a = to_double(p_ring[e]);
    const PointD b = to_double(p_ring[(e + 1) % 3]);
    const double edge = std::hypot(b.x - a.x, b.y - a.y) * s;
    EXPECT_NEAR(dist(end_point(cmds[0]), 0, end_point(cmds[1]), 0), edge, 1e-3) << e;
    EXPECT_NEAR(dist(end_point(cmds[1]), 0, end_point(cmds[3]), 0), 2 * r * s, 1e-3) << e;
    EXPECT_NEAR(dist(end_point(cmds[3]), 0, end_point(cmds[4]), 0), edge, 1e-3) << e;
    for (const std::size_t i : {2U, 3U, 5U, 6U}) {
      EXPECT_EQ(cmds[i].op, 'A');
      EXPECT_NEAR(cmds[i].args[0], r * s, 1e-3); // true circular arcs of the pen radius
      EXPECT_NEAR(cmds[i].args[1], r * s, 1e-3);
    }
  }
  // The band: offset(P, r + eps) with offset(P, r - eps) masked out.
  const auto band_pieces = elements(*find_by_id(root, "band"), "path");
  ASSERT_EQ(band_pieces.size(), 4U); // fill pass only: no outline for the band
  EXPECT_NEAR(parse_path(*attribute(*band_pieces[1], "d"))[2].args[0], (r + 1e6) * s, 1e-3);
  const auto hole_pieces = elements(*find_by_id(root, "band-hole"), "path");
  ASSERT_EQ(hole_pieces.size(), 4U);
  EXPECT_NEAR(parse_path(*attribute(*hole_pieces[1], "d"))[2].args[0], (r - 1e6) * s, 1e-3);

  // Everything lies inside the picture, whose drawing is at most 900 pixels (the default).
  std::istringstream vb(*attribute(root, "viewBox"));
  double x0 = 0, y0 = 0, w = 0, h = 0;
  vb >> x0 >> y0 >> w >> h;
  EXPECT_LE(w, 900 + 1e-3);
  EXPECT_GT(w, 800); // the wheel is about as wide as high
  EXPECT_EQ(std::stod(*attribute(root, "width")), std::ceil(w));
  for (const auto* path : elements(root, "path")) {
    for (const auto& c : parse_path(*attribute(*path, "d"))) {
      if (c.op != 'M' && c.op != 'L') continue;
      EXPECT_GE(c.args[0], 0);
      EXPECT_LE(c.args[0], w);
      EXPECT_GE(c.args[1], 0);
      EXPECT_LE(c.args[1], h);
    }
  }
}

TEST(SvgFigure, WithoutSolutionOnlyQIsDrawn) {
  DeconstructionFigure f;
  f.q = read_polygon(gen::country(12, 160, 50.0).text);
  f.radius = 1;
  f.tolerance = 0.5;
  const ptree doc = parse_xml(render::deconstruction_svg(f));
  EXPECT_NE(find_by_id(doc.get_child("svg"), "Q"), nullptr);
  EXPECT_EQ(find_by_id(doc.get_child("svg"), "offset"), nullptr);
  EXPECT_EQ(find_by_id(doc.get_child("svg"), "band"), nullptr);
}

TEST(SvgFigure, StrokeWithCircleAndArcShapes) {
  StrokeFigure f;
  const auto gesture = read_dollar_gesture(stroke_file("circle", 3));
  for (const auto& p : gesture) f.samples.push_back({p.x * 0.2, p.y * 0.2});
  f.pen_radius = 1.5;
  f.tolerance = 0.75;
  ShapeOutline circle;
  circle.kind = ShapeOutline::Kind::kCircle;
  circle.center = {30, 30};
  circle.radius = 10;
  f.shape = circle;
  const ptree doc = parse_xml(render::stroke_svg(f));
  const ptree& root = doc.get_child("svg");
  EXPECT_EQ(elements(*find_by_id(root, "samples"), "circle").size(), gesture.size());
  // No ink polygon given: the ink is the samples swept by the pen (one stadium per sample).
  EXPECT_EQ(elements(*find_by_id(root, "ink"), "path").size(), 2 * gesture.size());
  // The center line: a circle of radius 10 mm, which gives the pixel scale.
  const auto line = parse_path(*attribute(*elements(*find_by_id(root, "shape"), "path")[0], "d"));
  ASSERT_EQ(line.size(), 4U);
  const double s = line[1].args[0] / 10;
  EXPECT_NEAR(dist(end_point(line[0]), 0, end_point(line[1]), 0), 20 * s, 1e-3);
  // The shape's ink: an annulus of radii 10 ± 1.5 as four half-circle arcs.
  const auto ring =
      parse_path(*attribute(*elements(*find_by_id(root, "shape-ink"), "path")[0], "d"));
  std::vector<double> radii;
  for (const auto& c : ring) {
    if (c.op == 'A') radii.push_back(c.args[0] / s);
  }
  ASSERT_EQ(radii.size(), 4U);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(radii[i], i < 2 ? 11.5 : 8.5, 1e-3);

  // An open arc: a quarter circle drawn with the pen is an arc band with round caps.
  ShapeOutline arc;
  arc.kind = ShapeOutline::Kind::kArc;
  arc.center = {30, 30};
  arc.radius = 10;
  arc.start_rad = 0;
  arc.sweep_rad = std::numbers::pi / 2;
  f.shape = arc;
  const ptree doc2 = parse_xml(render::stroke_svg(f));
  const auto band = parse_path(
      *attribute(*elements(*find_by_id(doc2.get_child("svg"), "shape-ink"), "path")[0], "d"));
  std::vector<double> arc_radii;
  for (const auto& c : band) {
    if (c.op == 'A') arc_radii.push_back(c.args[0] / s);
  }
  ASSERT_EQ(arc_radii.size(), 4U);
  const double want[] = {11.5, 1.5, 8.5, 1.5};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(arc_radii[i], want[i], 1e-3);
  // Outer arc: a quarter turn of radius 11.5 mm.
  EXPECT_NEAR(dist(end_point(band[0]), 0, end_point(band[1]), 0), 11.5 * std::sqrt(2.0) * s, 1e-3);
  EXPECT_EQ(band[1].args[4], 1); // sweep flag: increasing angle, as the model's y axis is down
}

TEST(SvgFigure, FigureOfADeconstructionResult) {
  const PolygonSet q = read_polygon(gen::country(12, 160, 50.0).text);
  DeconstructResult yes;
  yes.answer = Answer::kYes;
  yes.params.radius = Rational(3, 2);
  yes.params.tolerance = Rational(1, 2);
  yes.params.precision = Rational(1, 16);
  yes.solution = polygon({{0, 0}, {1, 0}, {0, 1}});
  const auto f = render::deconstruction_figure(q, yes);
  EXPECT_EQ(f.radius, 1.5);
  EXPECT_EQ(f.tolerance, 0.5);
  ASSERT_TRUE(f.p.has_value());
  EXPECT_EQ(f.p->vertex_count(), 3U);
  EXPECT_EQ(f.caption.rfind("YES  r = 1.5  eps = 0.5  delta = 0.0625  (fast engine)", 0), 0U)
      << f.caption;
  EXPECT_NE(f.caption.find("|P| = 3"), std::string::npos);
  DeconstructResult no = yes;
  no.answer = Answer::kNo;
  no.solution = {};
  const auto g = render::deconstruction_figure(q, no);
  EXPECT_FALSE(g.p.has_value());
  EXPECT_EQ(g.caption.rfind("NO  ", 0), 0U);
  const ptree doc = parse_xml(render::deconstruction_svg(g));
  EXPECT_EQ(find_by_id(doc.get_child("svg"), "P"), nullptr);
}

TEST(SvgFigure, RefusesBadInputWithAClearError) {
  DeconstructionFigure f;
  EXPECT_THROW((void)render::deconstruction_svg(f), std::invalid_argument); // empty Q
  f.q = polygon({{0, 0}, {1, 0}, {0, 1}});
  f.radius = -1;
  EXPECT_THROW((void)render::deconstruction_svg(f), std::invalid_argument);
  f.radius = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)render::deconstruction_svg(f), std::invalid_argument);
  StrokeFigure s;
  s.samples = {{0, 0}, {std::numeric_limits<double>::infinity(), 1}};
  try {
    (void)render::stroke_svg(s);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos);
  }
  EXPECT_THROW(render::write_svg_file("/nonexistent-dir/x.svg", "<svg/>"), std::runtime_error);
}

} // namespace
} // namespace penshape::testing
