// The project's test-data generators: fixed seeds give fixed data; every kind of drawing comes
// out as a well-formed pen stroke with its truth; the hand's imperfections follow the measured
// numbers; generated polygons are valid regions; generated descriptors parse into the pen
// layout they describe and round-trip samples through the drivers' encoder and decoder.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "descriptor_gen.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "penshape/drivers/hid_descriptor.hpp"
#include "penshape/drivers/pen_decoder.hpp"
#include "penshape/drivers/pen_encoder.hpp"
#include "penshape/drivers/pen_layout.hpp"
#include "polygon_gen.hpp"
#include "stroke_files.hpp"
#include "stroke_gen.hpp"
#include "stroke_measurements.hpp"

namespace penshape::gen {
namespace {

std::vector<std::string> all_kinds() {
  std::vector<std::string> kinds = single_stroke_shape_kinds();
  for (const auto* group : {&multi_stroke_shape_kinds(), &non_shape_kinds()})
    kinds.insert(kinds.end(), group->begin(), group->end());
  return kinds;
}

double diagonal(const std::vector<StrokePoint>& p) {
  double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
  for (const auto& q : p) {
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  return std::hypot(x1 - x0, y1 - y0);
}

TEST(StrokeGenerator, TheSameSeedDrawsTheSameStrokes) {
  StrokeGenerator a(7), b(7), c(8);
  const Drawing da = a.draw("word"), db = b.draw("word"), dc = c.draw("word");
  EXPECT_EQ(to_jsonl(da, "w"), to_jsonl(db, "w"));
  EXPECT_NE(to_jsonl(da, "w"), to_jsonl(dc, "w"));
}

TEST(StrokeGenerator, EveryKindIsAWellFormedPenDrawingWithItsTruth) {
  StrokeGenerator gen(11);
  for (const auto& kind : all_kinds()) {
    for (const Speed speed : {Speed::kSlow, Speed::kFast}) {
      const Drawing d = gen.draw(kind, {speed});
      ASSERT_FALSE(d.strokes.empty()) << kind;
      EXPECT_FALSE(d.truth.empty()) << kind;
      EXPECT_EQ(d.is_shape, d.truth.count("freeform") == 0) << kind;
      double last_t = -1.0;
      for (const auto& s : d.strokes) {
        ASSERT_GE(s.points.size(), 2U) << kind;
        ASSERT_EQ(s.pressure.size(), s.points.size()) << kind;
        for (std::size_t i = 0; i < s.points.size(); ++i) {
          EXPECT_GT(s.points[i].t, last_t + 0.001) << kind << " point " << i; // whole ms apart
          last_t = s.points[i].t;
          EXPECT_EQ(s.points[i].x, std::round(s.points[i].x)) << kind;
          EXPECT_GT(s.pressure[i], 0.0) << kind;
          EXPECT_LE(s.pressure[i], 1.0) << kind;
        }
      }
    }
  }
  EXPECT_THROW(gen.draw("unicorn"), std::invalid_argument);
}

TEST(StrokeGenerator, MultiStrokeKindsHaveTheirStrokeCounts) {
  StrokeGenerator gen(3);
  EXPECT_EQ(gen.draw("arrow1").strokes.size(), 1U);
  EXPECT_EQ(gen.draw("arrow2").strokes.size(), 2U);
  EXPECT_EQ(gen.draw("arrow3").strokes.size(), 3U);
  EXPECT_EQ(gen.draw("rectangle2").strokes.size(), 2U);
  EXPECT_EQ(gen.draw("rectangle4").strokes.size(), 4U);
  EXPECT_EQ(gen.draw("triangle3").strokes.size(), 3U);
}

// The closure gap of generated closed shapes follows the measured gap of real ones.
TEST(StrokeGenerator, ClosureGapsFollowTheMeasurements) {
  StrokeGenerator gen(5);
  double sum = 0.0;
  int n = 0;
  for (int i = 0; i < 60; ++i) {
    for (const char* kind : {"circle", "rectangle", "triangle"}) {
      const auto p = gen.draw(kind).strokes.front().points;
      sum += std::hypot(p.back().x - p.front().x, p.back().y - p.front().y) / diagonal(p);
      ++n;
    }
  }
  EXPECT_NEAR(sum / n, measured::kClosureGapMean, 0.5 * measured::kClosureGapMean);
}

// RMS radial residual of a circle about its centroid's mean radius: grows with size and speed.
double circle_wobble(StrokeGenerator& gen, double scale, Speed speed) {
  double sum = 0.0;
  for (int i = 0; i < 40; ++i) {
    const auto p = gen.draw("circle", {speed, scale}).strokes.front().points;
    double cx = 0, cy = 0;
    for (const auto& q : p)
      cx += q.x / static_cast<double>(p.size()), cy += q.y / static_cast<double>(p.size());
    std::vector<double> r;
    r.reserve(p.size());
    for (const auto& q : p) r.push_back(std::hypot(q.x - cx, q.y - cy));
    const double mean = std::accumulate(r.begin(), r.end(), 0.0) / static_cast<double>(r.size());
    double var = 0.0;
    for (double v : r) var += (v - mean) * (v - mean) / static_cast<double>(r.size());
    sum += std::sqrt(var);
  }
  return sum / 40;
}

TEST(StrokeGenerator, WobbleGrowsWithSizeAndSpeed) {
  StrokeGenerator gen(9);
  EXPECT_GT(circle_wobble(gen, 2.0, Speed::kMedium), 1.5 * circle_wobble(gen, 1.0, Speed::kMedium));
  EXPECT_GT(circle_wobble(gen, 1.0, Speed::kFast), circle_wobble(gen, 1.0, Speed::kSlow));
}

TEST(StrokeGenerator, DollarXmlCarriesTheStroke) {
  StrokeGenerator gen(1);
  const Drawing d = gen.draw("triangle");
  const std::string xml = to_dollar_xml(d.strokes.front(), "triangle01", 2, Speed::kFast);
  EXPECT_NE(xml.find("<Gesture Name=\"triangle01\" Subject=\"2\" Speed=\"fast\""),
            std::string::npos);
  std::size_t points = 0;
  for (std::size_t at = 0; (at = xml.find("<Point X=", at)) != std::string::npos; ++at) ++points;
  EXPECT_EQ(points, d.strokes.front().points.size());
}

TEST(PolygonGenerator, EveryPolygonIsAValidRegion) {
  for (const auto& p : polygon_suite(4)) {
    SCOPED_TRACE(p.name);
    const PolygonSet q = read_polygon_text(p.text);
    EXPECT_NO_THROW(validate_region(q));
    EXPECT_EQ(p.text.rfind("# generated by penshape", 0), 0U);
  }
  EXPECT_EQ(country(1, 1881, 1000).text, country(1, 1881, 1000).text);
  const PolygonSet holes = read_polygon_text(holes_and_islands(3, 100).text);
  std::size_t rings = 0;
  for (const auto& polygon : holes.polygons) rings += 1 + polygon.holes.size();
  EXPECT_EQ(rings, 1U + 3U + 2U); // the outer square, three holes, two islands
}

TEST(DescriptorGenerator, EveryDescriptorParsesIntoThePenItDescribes) {
  for (const auto& spec : pen_descriptor_specs()) {
    SCOPED_TRACE(spec.name);
    const auto parsed = drivers::parse_report_descriptor(pen_descriptor(spec));
    const auto layouts = drivers::find_pen_layouts(parsed);
    ASSERT_EQ(layouts.size(), 1U);
    const drivers::PenLayout& pen = layouts.front();
    EXPECT_EQ(pen.report_id, spec.report_id);
    EXPECT_EQ(pen.x_max(), spec.x_max);
    EXPECT_EQ(pen.y_max(), spec.y_max);
    EXPECT_EQ(pen.pressure_max(), static_cast<std::uint32_t>(spec.pressure_max));
    EXPECT_NEAR(pen.x_resolution, spec.x_max / spec.width_mm, 0.01 * pen.x_resolution);
    EXPECT_NEAR(pen.y_resolution, spec.y_max / spec.height_mm, 0.01 * pen.y_resolution);
    EXPECT_EQ(pen.tilt_x.present(), spec.tilt);
    EXPECT_TRUE(pen.tip.present());
    EXPECT_TRUE(pen.in_range.present());

    const drivers::PenDecoder decoder({pen});
    PenSample s, back;
    s.x = spec.x_max / 3, s.y = spec.y_max / 2, s.pressure = 100, s.tip = true, s.in_range = true;
    ASSERT_EQ(decoder.decode(drivers::encode_pen_report(pen, s), 5, back),
              drivers::DecodeStatus::kPen);
    EXPECT_EQ(back.x, s.x);
    EXPECT_EQ(back.y, s.y);
    EXPECT_EQ(back.pressure, s.pressure);
    EXPECT_TRUE(back.tip);
  }
}

} // namespace
} // namespace penshape::gen
