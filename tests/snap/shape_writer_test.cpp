// Shapes written back by penshape snap (clients/snap/svg_writer.hpp, xopp_strokes.hpp), read
// back and compared with the shape's known vertices (in the element's own coordinates): an
// arrow's bent shaft keeps its bends, a shaft that stops short of its tip leaves the gap (SVG:
// two subpaths; Xournal++: two strokes); a polygon (ShapeClass::kPolygon, 5..8 corners) and a
// diamond (a rhombus, any orientation) are an SVG <polygon> through their corners and a Xournal++
// stroke that closes on its first corner.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "snap/path_data.hpp"
#include "snap/svg_strokes.hpp"
#include "snap/svg_writer.hpp"
#include "snap/xopp_strokes.hpp"

namespace penshape::snap {
namespace {

// A certified recognition of `shape` with these vertices (root coordinates), ε 5, bound 1.
Recognition certified(ShapeClass shape, std::vector<PointD> vertices) {
  Recognition r;
  r.shape = shape;
  r.params.vertices = std::move(vertices);
  r.certificate.certified = true;
  r.certificate.epsilon = 5;
  r.certificate.bound = 1;
  r.certificate.pen_radius = 1;
  return r;
}

// An arrow: shaft (20, 10) -> (80, 10) -> (120, -20), barbs at the tip.
Recognition bent_arrow() {
  Recognition r = certified(ShapeClass::kArrow, {{20, 10}, {120, -20}, {110, -6}, {104, -14}});
  r.params.shaft_bends = {{80, 10}};
  return r;
}

// An L-shaped hexagon.
Recognition l_hexagon() {
  return certified(ShapeClass::kPolygon, {{0, 0}, {40, 0}, {40, 16}, {16, 16}, {16, 40}, {0, 40}});
}

// A flowchart diamond: a rhombus of half-diagonals 30 (across) and 18 (up), centre (40, 30).
Recognition flowchart_diamond() {
  return certified(ShapeClass::kDiamond, {{70, 30}, {40, 48}, {10, 30}, {40, 12}});
}

// The one stroke of an SVG document, replaced by `r`.
pugi::xml_node replaced_svg(pugi::xml_document& doc, const std::string& text,
                            const Recognition& r) {
  EXPECT_TRUE(doc.load_string(text.c_str()));
  std::vector<std::string> warnings;
  const std::vector<SvgPage> pages = read_svg_strokes(doc, text, {}, warnings);
  if (pages.size() != 1 || pages[0].strokes.size() != 1) {
    ADD_FAILURE() << "expected one stroke";
    return {};
  }
  return replace_svg_stroke(pages[0].strokes[0], r, 1.0);
}

// The one stroke of a Xournal++ page, replaced by `r`: its points as written.
std::string replaced_xopp(const std::string& text, const Recognition& r) {
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_string(text.c_str()));
  std::vector<std::string> warnings;
  const std::vector<XoppLayer> layers = read_xopp_strokes(doc, text, warnings);
  if (layers.size() != 1 || layers[0].strokes.size() != 1) {
    ADD_FAILURE() << "expected one stroke";
    return {};
  }
  replace_xopp_stroke(layers[0].strokes[0], r, 0.75);
  return doc.child("xournal").child("page").child("layer").child("stroke").child_value();
}

// The numbers of a list separated by spaces or commas.
std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::size_t at = 0;
  double v = 0;
  int used = 0;
  while (std::sscanf(text.c_str() + at, "%lf%n", &v, &used) == 1 ||
         std::sscanf(text.c_str() + at, ",%lf%n", &v, &used) == 1) {
    out.push_back(v);
    at += static_cast<std::size_t>(used);
  }
  return out;
}

std::string xopp_page(const std::string& points) {
  return "<xournal><page width='200' height='200'><layer>"
         "<stroke tool='pen' color='#000000ff' width='1.5'>" +
         points + "</stroke></layer></page></xournal>";
}

TEST(ArrowWriter, SvgPathHoldsTheShaftsBend) {
  // The stroke sits in a group moved by (10, 5): the path is written in its own coordinates.
  pugi::xml_document doc;
  const pugi::xml_node out = replaced_svg(
      doc,
      "<svg xmlns='http://www.w3.org/2000/svg'><g transform='translate(10,5)'>"
      "<path id='s' d='M 10,5 L 70,5 L 110,-25' style='fill:none;stroke:#000;stroke-width:2'/>"
      "</g></svg>",
      bent_arrow());
  EXPECT_STREQ(out.name(), "path");
  EXPECT_STREQ(out.attribute("id").value(), "s");
  EXPECT_STREQ(out.attribute("data-penshape-class").value(), "arrow");
  const std::vector<Subpath> sub = parse_path_data(out.attribute("d").value(), 0.01);
  ASSERT_EQ(sub.size(), 2u); // the shaft, the head
  EXPECT_EQ(sub[0].points, (std::vector<PointD>{{10, 5}, {70, 5}, {110, -25}}));
  EXPECT_EQ(sub[1].points, (std::vector<PointD>{{100, -11}, {110, -25}, {94, -19}}));
}

TEST(ArrowWriter, XournalStrokeHoldsTheShaftsBend) {
  const std::string pts = replaced_xopp(xopp_page("20 10 80 10 120 -20"), bent_arrow());
  // One line through every piece: shaft with its bend, then the head (the tip retraced).
  EXPECT_EQ(numbers(pts),
            (std::vector<double>{20, 10, 80, 10, 120, -20, 110, -6, 120, -20, 104, -14}));
}

// An arrow whose shaft stops short of its tip: shaft (20, 10) -> (80, 10), tip (120, 10).
Recognition gapped_arrow() {
  Recognition r = certified(ShapeClass::kArrow, {{20, 10}, {120, 10}, {104, 22}, {104, -2}});
  r.params.shaft_end = PointD{80, 10};
  return r;
}

TEST(ArrowWriter, SvgPathLeavesTheGapBeforeTheTip) {
  pugi::xml_document doc;
  const pugi::xml_node out =
      replaced_svg(doc,
                   "<svg xmlns='http://www.w3.org/2000/svg'>"
                   "<path id='s' d='M 20,10 L 80,10' style='fill:none;stroke:#000;stroke-width:2'/>"
                   "</svg>",
                   gapped_arrow());
  const std::vector<Subpath> sub = parse_path_data(out.attribute("d").value(), 0.01);
  ASSERT_EQ(sub.size(), 2u); // the shaft as far as it goes, the head
  EXPECT_EQ(sub[0].points, (std::vector<PointD>{{20, 10}, {80, 10}}));
  EXPECT_EQ(sub[1].points, (std::vector<PointD>{{104, 22}, {120, 10}, {104, -2}}));
}

TEST(ArrowWriter, XournalWritesTheShaftAndTheHeadAsTwoStrokes) {
  pugi::xml_document doc;
  const std::string text = xopp_page("20 10 80 10");
  ASSERT_TRUE(doc.load_string(text.c_str()));
  std::vector<std::string> warnings;
  const std::vector<XoppLayer> layers = read_xopp_strokes(doc, text, warnings);
  ASSERT_EQ(layers.size(), 1u);
  ASSERT_EQ(layers[0].strokes.size(), 1u);
  const std::string written = replace_xopp_stroke(layers[0].strokes[0], gapped_arrow(), 0.75);
  std::vector<std::vector<double>> lines;
  for (const pugi::xml_node n : doc.child("xournal").child("page").child("layer").children()) {
    EXPECT_STREQ(n.name(), "stroke");
    EXPECT_STREQ(n.attribute("tool").value(), "pen");
    lines.push_back(numbers(n.child_value()));
  }
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], (std::vector<double>{20, 10, 80, 10}));
  EXPECT_EQ(lines[1], (std::vector<double>{104, 22, 120, 10, 104, -2}));
  // The text written (spliced into the file in place of the stroke) holds both strokes.
  EXPECT_EQ(written.find("<stroke"), 0u);
  EXPECT_NE(written.find("<stroke", 1), std::string::npos);
}

// The SVG path `d` replaced by `r`: an SVG <polygon> of class `name` through `corners`.
void expect_svg_polygon(const std::string& d, const Recognition& r, const char* name,
                        const std::vector<double>& corners) {
  pugi::xml_document doc;
  const pugi::xml_node out =
      replaced_svg(doc,
                   "<svg xmlns='http://www.w3.org/2000/svg'><path id='s' d='" + d +
                       "' style='fill:none;stroke:#000;stroke-width:2'/></svg>",
                   r);
  EXPECT_STREQ(out.name(), "polygon");
  EXPECT_STREQ(out.attribute("data-penshape-class").value(), name);
  const std::string pts = out.attribute("points").value();
  EXPECT_EQ(numbers(pts), corners) << pts;
}

TEST(PolygonWriter, SvgPolygonThroughTheCorners) {
  expect_svg_polygon("M 0,0 L 40,1 L 39,16 L 16,15 L 16,40 L 0,39 Z", l_hexagon(), "polygon",
                     {0, 0, 40, 0, 40, 16, 16, 16, 16, 40, 0, 40});
}

TEST(PolygonWriter, XournalStrokeClosesOnItsFirstCorner) {
  const std::string pts =
      replaced_xopp(xopp_page("0 0 40 1 39 16 16 15 16 40 0 39 0 0"), l_hexagon());
  EXPECT_EQ(numbers(pts), (std::vector<double>{0, 0, 40, 0, 40, 16, 16, 16, 16, 40, 0, 40, 0, 0}));
}

TEST(DiamondWriter, SvgPolygonThroughTheCorners) {
  expect_svg_polygon("M 70,31 L 41,48 L 10,29 L 39,12 Z", flowchart_diamond(), "diamond",
                     {70, 30, 40, 48, 10, 30, 40, 12});
}

TEST(DiamondWriter, XournalStrokeClosesOnItsFirstCorner) {
  const std::string pts =
      replaced_xopp(xopp_page("70 31 41 48 10 29 39 12 70 31"), flowchart_diamond());
  EXPECT_EQ(numbers(pts), (std::vector<double>{70, 30, 40, 48, 10, 30, 40, 12, 70, 30}));
}

} // namespace
} // namespace penshape::snap
