// Polygons (ShapeClass::kPolygon, 5..8 corners) written back by penshape snap
// (clients/snap/svg_writer.hpp, xopp_strokes.hpp): an SVG <polygon> through the corners, and a
// Xournal++ stroke that closes on its first corner.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "snap/svg_strokes.hpp"
#include "snap/svg_writer.hpp"
#include "snap/xopp_strokes.hpp"

namespace penshape::snap {
namespace {

// An L-shaped hexagon (root coordinates).
Recognition l_hexagon() {
  Recognition r;
  r.shape = ShapeClass::kPolygon;
  r.params.vertices = {{0, 0}, {40, 0}, {40, 16}, {16, 16}, {16, 40}, {0, 40}};
  r.certificate.certified = true;
  r.certificate.epsilon = 5;
  r.certificate.bound = 1;
  r.certificate.pen_radius = 1;
  return r;
}

TEST(PolygonWriter, SvgPolygonThroughTheCorners) {
  const std::string text =
      "<svg xmlns='http://www.w3.org/2000/svg'>"
      "<path id='s' d='M 0,0 L 40,1 L 39,16 L 16,15 L 16,40 L 0,39 Z' "
      "style='fill:none;stroke:#000;stroke-width:2'/></svg>";
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(text.c_str()));
  std::vector<std::string> warnings;
  const std::vector<SvgPage> pages = read_svg_strokes(doc, text, {}, warnings);
  ASSERT_EQ(pages.size(), 1u);
  ASSERT_EQ(pages[0].strokes.size(), 1u);
  const pugi::xml_node out = replace_svg_stroke(pages[0].strokes[0], l_hexagon(), 1.0);
  EXPECT_STREQ(out.name(), "polygon");
  EXPECT_STREQ(out.attribute("data-penshape-class").value(), "polygon");
  std::vector<double> xy;
  const std::string pts = out.attribute("points").value();
  std::size_t at = 0;
  double v = 0;
  int used = 0;
  while (std::sscanf(pts.c_str() + at, "%lf%n", &v, &used) == 1 ||
         std::sscanf(pts.c_str() + at, ",%lf%n", &v, &used) == 1) {
    xy.push_back(v);
    at += static_cast<std::size_t>(used);
  }
  EXPECT_EQ(xy, (std::vector<double>{0, 0, 40, 0, 40, 16, 16, 16, 16, 40, 0, 40})) << pts;
}

TEST(PolygonWriter, XournalStrokeClosesOnItsFirstCorner) {
  const std::string text =
      "<xournal><page width='200' height='200'><layer>"
      "<stroke tool='pen' color='#000000ff' width='1.5'>0 0 40 1 39 16 16 15 16 40 0 39 0 0"
      "</stroke></layer></page></xournal>";
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(text.c_str()));
  std::vector<std::string> warnings;
  const std::vector<XoppLayer> layers = read_xopp_strokes(doc, text, warnings);
  ASSERT_EQ(layers.size(), 1u);
  ASSERT_EQ(layers[0].strokes.size(), 1u);
  replace_xopp_stroke(layers[0].strokes[0], l_hexagon(), 0.75);
  std::vector<double> xy;
  const std::string pts =
      doc.child("xournal").child("page").child("layer").child("stroke").child_value();
  std::size_t at = 0;
  double v = 0;
  int used = 0;
  while (std::sscanf(pts.c_str() + at, "%lf%n", &v, &used) == 1) {
    xy.push_back(v);
    at += static_cast<std::size_t>(used);
  }
  EXPECT_EQ(xy, (std::vector<double>{0, 0, 40, 0, 40, 16, 16, 16, 16, 40, 0, 40, 0, 0}));
}

} // namespace
} // namespace penshape::snap
