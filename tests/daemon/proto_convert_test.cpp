#include "penshape/daemon/proto_convert.hpp"
#include "polygon_gen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using penshape::Rational;
using penshape::daemon::FieldError;
using penshape::daemon::Limits;
namespace v1 = penshape::v1;

// A generated polygon of 64 vertices (a spiky star, tests/support/gen) in the polygon files'
// format: "x y" per line, '#' header lines.
std::string star64() { return penshape::gen::spikes(5, 32, 30.0, 100.0).text; }

v1::PolygonSet read_polygon(const std::string& text) {
  std::istringstream in(text);
  v1::PolygonSet set;
  v1::Ring* ring = set.add_polygons()->mutable_outer();
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double x = 0;
    double y = 0;
    fields >> x >> y;
    auto* p = ring->add_points();
    p->set_x(x);
    p->set_y(y);
  }
  return set;
}

// GMP's own exact double conversion, independent of penshape::exact().
Rational gmp_exact(double v) {
  mpq_t q;
  mpq_init(q);
  mpq_set_d(q, v);
  Rational r(q);
  mpq_clear(q);
  return r;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const FieldError& e) {
    return e.what();
  }
  return "no error";
}

v1::PolygonSet triangle() {
  v1::PolygonSet set;
  auto* ring = set.add_polygons()->mutable_outer();
  for (auto [x, y] : {std::pair{0.0, 0.0}, {4.0, 0.0}, {0.0, 3.0}, {0.1, 0.2}}) {
    auto* p = ring->add_points();
    p->set_x(x);
    p->set_y(y);
  }
  return set;
}

TEST(ProtoConvert, PolygonConvertsExactlyAndRoundTrips) {
  const v1::PolygonSet message = read_polygon(star64());
  ASSERT_EQ(message.polygons(0).outer().points_size(), 64);
  const penshape::PolygonSet set = penshape::daemon::polygon_set_from_proto(message, "polygon", {});
  ASSERT_EQ(set.vertex_count(), 64U);
  for (int i = 0; i < 64; ++i) {
    const auto& p = message.polygons(0).outer().points(i);
    const auto& e = set.polygons[0].outer[static_cast<std::size_t>(i)];
    EXPECT_EQ(e.x, gmp_exact(p.x()));
    EXPECT_EQ(e.y, gmp_exact(p.y()));
  }
  v1::PolygonSet back;
  penshape::daemon::to_proto(set, &back);
  ASSERT_EQ(back.polygons(0).outer().exact_points_size(), 64);
  for (int i = 0; i < 64; ++i) {
    EXPECT_EQ(back.polygons(0).outer().points(i).x(), message.polygons(0).outer().points(i).x());
    EXPECT_EQ(back.polygons(0).outer().points(i).y(), message.polygons(0).outer().points(i).y());
  }
  // The exact strings alone reproduce the same set.
  back.mutable_polygons(0)->mutable_outer()->clear_points();
  const auto again = penshape::daemon::polygon_set_from_proto(back, "polygon", {});
  EXPECT_EQ(again.polygons[0].outer, set.polygons[0].outer);
}

TEST(ProtoConvert, NonDyadicDoublesKeepTheirExactBinaryValue) {
  const auto set = penshape::daemon::polygon_set_from_proto(triangle(), "polygon", {});
  // 0.1 is not 1/10: it is the double nearest to it, 3602879701896397 / 2^55.
  EXPECT_EQ(set.polygons[0].outer[3].x, Rational("3602879701896397/36028797018963968"));
  EXPECT_NE(set.polygons[0].outer[3].x, Rational(1, 10));
}

TEST(ProtoConvert, ExactPointsWinAndAreValidated) {
  v1::PolygonSet set = triangle();
  auto* ring = set.mutable_polygons(0)->mutable_outer();
  for (const char* v : {"0", "4", "0", "1/10"}) {
    auto* e = ring->add_exact_points();
    e->set_x(v);
    e->set_y("-6/4");
  }
  const auto converted = penshape::daemon::polygon_set_from_proto(set, "q", {});
  EXPECT_EQ(converted.polygons[0].outer[3].x, Rational(1, 10));
  EXPECT_EQ(converted.polygons[0].outer[3].y, Rational(-3, 2)); // canonicalised
  EXPECT_EQ(converted.polygons[0].outer[3].y.get_den(), 2);

  ring->mutable_exact_points(2)->set_y("1/0");
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(set, "q", {}); }),
            "q.polygons[0].outer.exact_points[2].y has a zero denominator");
  ring->mutable_exact_points(2)->set_y("1.5");
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(set, "q", {}); }),
            "q.polygons[0].outer.exact_points[2].y is '1.5'; expected \"p/q\" or \"p\" (decimal "
            "integers, optional '-')");
  ring->mutable_exact_points()->RemoveLast();
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(set, "q", {}); }),
            "q.polygons[0].outer.exact_points has 3 entries but points has 4");
}

TEST(ProtoConvert, BadCoordinatesAreNamedByTheirPath) {
  v1::PolygonSet set = triangle();
  set.mutable_polygons(0)->mutable_outer()->mutable_points(3)->set_x(std::nan(""));
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(set, "polygon", {}); }),
            "polygon.polygons[0].outer.points[3].x is NaN");
  set = triangle();
  auto* hole = set.mutable_polygons(0)->add_holes();
  for (int i = 0; i < 3; ++i) hole->add_points()->set_x(1);
  hole->mutable_points(1)->set_y(-std::numeric_limits<double>::infinity());
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(set, "polygon", {}); }),
            "polygon.polygons[0].holes[0].points[1].y is infinite");
  hole->mutable_points(1)->set_y(2e12);
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(set, "polygon", {}); }),
            "polygon.polygons[0].holes[0].points[1].y is 2000000000000, beyond the limit "
            "|coordinate| <= 1000000000000");
  hole->mutable_points()->RemoveLast();
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(set, "polygon", {}); }),
            "polygon.polygons[0].holes[0] has 2 points; a ring needs at least 3");
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto({}, "polygon", {}); }),
            "polygon.polygons is empty");
  v1::PolygonSet no_outer;
  no_outer.add_polygons();
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(no_outer, "polygon", {}); }),
            "polygon.polygons[0].outer is missing");
}

TEST(ProtoConvert, VertexLimitIsEnforcedBeforeConversion) {
  Limits limits;
  limits.max_vertices = 63;
  const v1::PolygonSet message = read_polygon(star64());
  EXPECT_EQ(error_of([&] { penshape::daemon::polygon_set_from_proto(message, "polygon", limits); }),
            "polygon has 64 vertices, beyond the limit 63");
}

v1::DeconstructRequest request(double r, double eps) {
  v1::DeconstructRequest req;
  req.mutable_radius()->set_value(r);
  req.mutable_tolerance()->set_value(eps);
  return req;
}

TEST(ProtoConvert, DeconstructParameters) {
  auto params = penshape::daemon::deconstruct_params_from_proto(request(2, 1), {});
  EXPECT_EQ(params.radius, 2);
  EXPECT_EQ(params.tolerance, 1);
  EXPECT_EQ(params.precision, Rational(1, 8)); // default eps / 8
  EXPECT_EQ(params.engine, penshape::EngineKind::kFast);

  auto req = request(2, 1);
  req.mutable_precision()->set_rational("1/3");
  req.set_engine(v1::ENGINE_REFERENCE);
  params = penshape::daemon::deconstruct_params_from_proto(req, {});
  EXPECT_EQ(params.precision, Rational(1, 3));
  EXPECT_EQ(params.engine, penshape::EngineKind::kReference);

  auto message = [](const v1::DeconstructRequest& r) {
    return error_of([&] { penshape::daemon::deconstruct_params_from_proto(r, {}); });
  };
  EXPECT_EQ(message(v1::DeconstructRequest{}), "radius is missing");
  EXPECT_EQ(message(request(0, 1)), "radius must be > 0");
  EXPECT_EQ(message(request(1, -1)), "tolerance must be > 0");
  EXPECT_EQ(message(request(std::nan(""), 1)), "radius.value is NaN");
  req = request(1, 1);
  req.mutable_precision()->set_value(1);
  EXPECT_EQ(message(req), "precision must be < tolerance (delta < eps)");
  // delta >= r / 2^20: exactly at the bound passes, just below fails.
  req = request(1, 1);
  req.mutable_precision()->set_rational("1/1048576");
  EXPECT_NO_THROW(penshape::daemon::deconstruct_params_from_proto(req, {}));
  req.mutable_precision()->set_rational("1/1048577");
  EXPECT_EQ(message(req),
            "precision must be >= radius / 1048576 (finer precisions need disk approximations "
            "beyond the engine's limit)");
  req = request(1, 1);
  req.set_engine(static_cast<v1::Engine>(9));
  EXPECT_EQ(message(req), "engine is 9, not a known Engine");
}

TEST(ProtoConvert, StrokesAreValidated) {
  v1::Stroke stroke;
  stroke.mutable_tablet()->set_x_max(100);
  stroke.mutable_tablet()->set_y_max(100);
  stroke.mutable_tablet()->set_x_resolution(10);
  stroke.mutable_tablet()->set_y_resolution(10);
  for (int i = 0; i < 3; ++i) {
    auto* s = stroke.add_samples();
    s->set_time_us(std::int64_t{1000} * i);
    s->set_x(10 * i);
    s->set_y(50);
    s->set_tip(i < 2);
  }
  const penshape::Stroke converted =
      penshape::daemon::stroke_from_proto(stroke, "stroke", {}, true);
  ASSERT_EQ(converted.samples.size(), 3U);
  EXPECT_EQ(converted.samples[2].x, 20);
  EXPECT_FALSE(converted.samples[2].tip);
  v1::Stroke back;
  penshape::daemon::to_proto(converted, &back);
  EXPECT_EQ(back.SerializeAsString(), stroke.SerializeAsString());

  auto message = [](const v1::Stroke& s, bool needs_resolution = true) {
    return error_of(
        [&] { penshape::daemon::stroke_from_proto(s, "stroke", {}, needs_resolution); });
  };
  v1::Stroke bad = stroke;
  bad.mutable_samples(2)->set_time_us(10);
  EXPECT_EQ(message(bad), "stroke.samples[2].time_us goes back in time (10 < 1000)");
  bad = stroke;
  bad.mutable_samples(1)->set_x(101);
  EXPECT_EQ(message(bad), "stroke.samples[1].x is 101, outside 0..tablet.x_max (100)");
  bad = stroke;
  bad.mutable_tablet()->set_y_resolution(0);
  EXPECT_EQ(message(bad), "stroke.tablet.y_resolution must be > 0 (device units per millimetre)");
  EXPECT_EQ(message(bad, false), "no error");
  bad.mutable_tablet()->set_x_resolution(std::nan(""));
  EXPECT_EQ(message(bad), "stroke.tablet.x_resolution is NaN");
  bad = stroke;
  bad.clear_samples();
  EXPECT_EQ(message(bad), "stroke.samples is empty");
  Limits two;
  two.max_stroke_samples = 2;
  EXPECT_EQ(error_of([&] { penshape::daemon::stroke_from_proto(stroke, "stroke", two, true); }),
            "stroke.samples has 3 samples, beyond the limit 2");
}

// Exact strings are GMP's own ("num" or "num/den"), also where they are formatted without GMP
// (both parts in a machine word): signs, whole numbers, powers of two and other denominators,
// and values beyond a word on either side.
TEST(ProtoConvert, ExactStringsAreGmpsOwn) {
  std::vector<Rational> values{Rational(0),
                               Rational(-1),
                               Rational(7),
                               Rational(-3, 4),
                               Rational(1, 3),
                               Rational("9223372036854775807"),
                               Rational("-9223372036854775808"),
                               Rational("9223372036854775808"),
                               Rational("1/18446744073709551615"),
                               Rational("-5/18446744073709551616")};
  std::mt19937_64 rng(26);
  for (int i = 0; i < 300; ++i) {
    Rational v(mpz_class(static_cast<long>(rng() >> static_cast<unsigned>(1 + i % 62))));
    mpq_div_2exp(v.get_mpq_t(), v.get_mpq_t(), static_cast<mp_bitcnt_t>(i % 70));
    values.push_back(i % 3 == 0 ? Rational(-v) : v);
  }
  penshape::PolygonSet set;
  set.polygons.emplace_back();
  for (std::size_t i = 0; i + 1 < values.size(); ++i) {
    set.polygons[0].outer.push_back({values[i], values[i + 1]});
  }
  v1::PolygonSet message;
  penshape::daemon::to_proto(set, &message);
  for (std::size_t i = 0; i + 1 < values.size(); ++i) {
    const auto& e = message.polygons(0).outer().exact_points(static_cast<int>(i));
    EXPECT_EQ(e.x(), values[i].get_str(10));
    EXPECT_EQ(e.y(), values[i + 1].get_str(10));
  }
  v1::ExactScalar scalar;
  for (const Rational& v : values) {
    penshape::daemon::to_proto(v, &scalar);
    EXPECT_EQ(scalar.rational(), v.get_str(10));
  }
}

TEST(ProtoConvert, DeconstructResultCarriesExactValues) {
  penshape::DeconstructResult result;
  result.answer = penshape::Answer::kYes;
  result.engine = penshape::EngineKind::kReference;
  result.params.radius = Rational(3, 2);
  result.params.tolerance = Rational(1, 2);
  result.params.precision = Rational(1, 16);
  result.hausdorff_bound = Rational(7, 16);
  result.disk_vertices = 48;
  result.solution = penshape::daemon::polygon_set_from_proto(triangle(), "p", {});
  v1::DeconstructResponse response;
  penshape::daemon::to_proto(result, &response);
  EXPECT_EQ(response.answer(), v1::ANSWER_YES);
  EXPECT_EQ(response.params().engine(), v1::ENGINE_REFERENCE);
  EXPECT_EQ(response.params().radius().rational(), "3/2");
  EXPECT_EQ(response.params().radius().approx(), 1.5);
  EXPECT_EQ(response.params().precision().rational(), "1/16");
  EXPECT_EQ(response.certificate().hausdorff_bound().rational(), "7/16");
  EXPECT_EQ(response.certificate().disk_vertices(), 48U);
  EXPECT_EQ(response.solution().polygons(0).outer().exact_points(3).x(),
            "3602879701896397/36028797018963968");
  EXPECT_EQ(response.solution().polygons(0).outer().points(3).x(), 0.1);

  result.answer = penshape::Answer::kNo;
  v1::DeconstructResponse no;
  penshape::daemon::to_proto(result, &no);
  EXPECT_EQ(no.answer(), v1::ANSWER_NO);
  EXPECT_EQ(no.solution().polygons_size(), 0); // only YES carries P
  EXPECT_FALSE(no.certificate().has_hausdorff_bound());
}

} // namespace
