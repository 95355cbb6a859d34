// Arrows written back by penshape snap (clients/snap/svg_writer.hpp, xopp_strokes.hpp): a bent
// shaft's bends are in what is written. The SVG path is read back with the snap's path-data
// parser and the Xournal++ stroke's points as numbers, and compared with the arrow's known
// vertices (in the element's own coordinates).
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

// An arrow (root coordinates): shaft (20, 10) -> (80, 10) -> (120, -20), barbs at the tip.
Recognition bent_arrow() {
  Recognition r;
  r.shape = ShapeClass::kArrow;
  r.params.vertices = {{20, 10}, {120, -20}, {110, -6}, {104, -14}};
  r.params.shaft_bends = {{80, 10}};
  r.certificate.certified = true;
  r.certificate.epsilon = 5;
  r.certificate.bound = 1;
  r.certificate.pen_radius = 1;
  return r;
}

TEST(ArrowWriter, SvgPathHoldsTheShaftsBend) {
  // The stroke sits in a group moved by (10, 5): the path is written in its own coordinates.
  const std::string text =
      "<svg xmlns='http://www.w3.org/2000/svg'><g transform='translate(10,5)'>"
      "<path id='s' d='M 10,5 L 70,5 L 110,-25' style='fill:none;stroke:#000;stroke-width:2'/>"
      "</g></svg>";
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(text.c_str()));
  std::vector<std::string> warnings;
  const std::vector<SvgPage> pages = read_svg_strokes(doc, text, {}, warnings);
  ASSERT_EQ(pages.size(), 1u);
  ASSERT_EQ(pages[0].strokes.size(), 1u);
  const pugi::xml_node out = replace_svg_stroke(pages[0].strokes[0], bent_arrow(), 1.0);
  EXPECT_STREQ(out.name(), "path");
  EXPECT_STREQ(out.attribute("id").value(), "s");
  EXPECT_STREQ(out.attribute("data-penshape-class").value(), "arrow");
  const std::vector<Subpath> sub = parse_path_data(out.attribute("d").value(), 0.01);
  ASSERT_EQ(sub.size(), 2u); // the shaft, the head
  EXPECT_EQ(sub[0].points, (std::vector<PointD>{{10, 5}, {70, 5}, {110, -25}}));
  EXPECT_EQ(sub[1].points, (std::vector<PointD>{{100, -11}, {110, -25}, {94, -19}}));
}

TEST(ArrowWriter, XournalStrokeHoldsTheShaftsBend) {
  const std::string text =
      "<xournal><page width='200' height='200'><layer>"
      "<stroke tool='pen' color='#000000ff' width='1.5'>20 10 80 10 120 -20</stroke>"
      "</layer></page></xournal>";
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(text.c_str()));
  std::vector<std::string> warnings;
  const std::vector<XoppLayer> layers = read_xopp_strokes(doc, text, warnings);
  ASSERT_EQ(layers.size(), 1u);
  ASSERT_EQ(layers[0].strokes.size(), 1u);
  replace_xopp_stroke(layers[0].strokes[0], bent_arrow(), 0.75);
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
  // One line through every piece: shaft with its bend, then the head (the tip retraced).
  EXPECT_EQ(xy, (std::vector<double>{20, 10, 80, 10, 120, -20, 110, -6, 120, -20, 104, -14}));
}

} // namespace
} // namespace penshape::snap
