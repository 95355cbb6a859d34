// Geometry RPCs on the real engine give the same results as the core library called directly.
// Built only with PENSHAPE_DAEMON_WITH_ENGINE (the engine is linked).
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <future>
#include <sstream>
#include <string>
#include <thread>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/search.hpp"
#include "penshape/core/simplify.hpp"
#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/v1/geometry.grpc.pb.h"
#include "polygon_gen.hpp"

namespace {

using namespace std::chrono_literals;
namespace v1 = penshape::v1;

// The polygons, generated (tests/support/gen): the RPCs must answer as the core library does.
// A YES case at r = 1, eps = 1/10 (a convex hexagon offset by 1, chords within 0.02).
std::string rounded_hexagon() {
  return penshape::gen::rounded_convex(8, 6, 10.0, 1.0, 0.02).q.text;
}
// A NO case at r = 1, eps = 1/10: a square's corners are (sqrt 2 - 1) r from any offset by r.
std::string square(int side) {
  const std::string s = std::to_string(side);
  return "0 0\n" + s + " 0\n" + s + " " + s + "\n0 " + s + "\n";
}
// A coastline about 100 units across, and a large one of 1,881 vertices.
std::string coast() { return penshape::gen::country(12, 160, 50.0).text; }
std::string large_coast() { return penshape::gen::country(4, 1881, 1000.0).text; }

// "x y" lines as exact decimals → exact rationals ("123/100"), so nothing is rounded.
std::string decimal_to_rational(const std::string& text) {
  const std::size_t dot = text.find('.');
  if (dot == std::string::npos) return text;
  std::string digits = text;
  digits.erase(dot, 1);
  mpz_class denominator;
  mpz_ui_pow_ui(denominator.get_mpz_t(), 10, text.size() - dot - 1);
  penshape::Rational q(mpz_class(digits, 10), denominator);
  q.canonicalize();
  return q.get_str(10);
}

v1::PolygonSet read_exact_polygon(const std::string& text) {
  std::istringstream in(text);
  v1::PolygonSet set;
  v1::Ring* ring = set.add_polygons()->mutable_outer();
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string x, y;
    fields >> x >> y;
    auto* p = ring->add_exact_points();
    p->set_x(decimal_to_rational(x));
    p->set_y(decimal_to_rational(y));
  }
  return set;
}

class GeometryEngineRpc : public ::testing::Test {
 protected:
  GeometryEngineRpc() {
    penshape::daemon::ServerOptions options;
    options.address = "unix-abstract:penshape-engine-test-" + std::to_string(::getpid());
    server_ = std::make_unique<penshape::daemon::PenshapeServer>(
        options, penshape::daemon::ServerParts{
                     nullptr, penshape::daemon::make_core_geometry_backend(), nullptr});
    stub_ = v1::Geometry::NewStub(
        grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  }
  std::unique_ptr<penshape::daemon::PenshapeServer> server_;
  std::unique_ptr<v1::Geometry::Stub> stub_;
};

struct Case {
  std::string what;
  std::string text;
  const char* radius;
  const char* tolerance;
  v1::Answer impossible; // the answer the data's documentation rules out
};

TEST_F(GeometryEngineRpc, DeconstructEqualsTheCoreLibrary) {
  const Case cases[] = {
      {"rounded hexagon", rounded_hexagon(), "1", "1/10", v1::ANSWER_NO},
      {"rounded heptagon", penshape::gen::rounded_convex(3, 7, 12.0, 1.0, 0.02).q.text, "1", "1/10",
       v1::ANSWER_NO},
      {"square 5", square(5), "1", "1/10", v1::ANSWER_YES},
      {"square 8", square(8), "1", "1/10", v1::ANSWER_YES},
      {"coast", coast(), "10", "5", v1::ANSWER_UNSPECIFIED},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    v1::DeconstructRequest request;
    *request.mutable_polygon() = read_exact_polygon(c.text);
    request.mutable_radius()->set_rational(c.radius);
    request.mutable_tolerance()->set_rational(c.tolerance);
    grpc::ClientContext ctx;
    ctx.set_deadline(std::chrono::system_clock::now() + 120s);
    v1::DeconstructResponse response;
    const grpc::Status status = stub_->Deconstruct(&ctx, request, &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
    EXPECT_NE(response.answer(), c.impossible);

    const penshape::daemon::Limits limits;
    const penshape::PolygonSet q =
        penshape::daemon::polygon_set_from_proto(request.polygon(), "polygon", limits);
    const penshape::DeconstructResult direct =
        penshape::deconstruct(q, penshape::daemon::deconstruct_params_from_proto(request, limits));
    EXPECT_EQ(response.answer(), penshape::daemon::to_proto(direct.answer));
    v1::PolygonSet expected;
    penshape::daemon::to_proto(direct.solution, &expected);
    EXPECT_EQ(response.solution().SerializeAsString(), expected.SerializeAsString());
    if (direct.answer == penshape::Answer::kYes) {
      EXPECT_EQ(response.certificate().hausdorff_bound().rational(),
                direct.hausdorff_bound.get_str(10));
    }
  }
}

TEST_F(GeometryEngineRpc, SimplifyEqualsTheCoreSimplification) {
  v1::DeconstructRequest request;
  *request.mutable_polygon() = read_exact_polygon(rounded_hexagon());
  request.mutable_radius()->set_rational("1");
  request.mutable_tolerance()->set_rational("1/2");
  request.set_simplify(true);
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + 120s);
  v1::DeconstructResponse response;
  const grpc::Status status = stub_->Deconstruct(&ctx, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_EQ(response.answer(), v1::ANSWER_YES);
  ASSERT_TRUE(response.has_simplification());

  const penshape::daemon::Limits limits;
  const penshape::PolygonSet q =
      penshape::daemon::polygon_set_from_proto(request.polygon(), "polygon", limits);
  const auto params = penshape::daemon::deconstruct_params_from_proto(request, limits);
  const penshape::SimplifyResult direct =
      penshape::simplify_solution(q, penshape::deconstruct(q, params));
  EXPECT_EQ(response.simplification().simplified(), direct.simplified);
  EXPECT_EQ(response.simplification().raw_vertices(), direct.raw_vertices);
  EXPECT_EQ(response.simplification().solution_vertices(), direct.solution_vertices);
  EXPECT_LE(response.simplification().solution_vertices(),
            response.simplification().raw_vertices());
  v1::PolygonSet expected;
  penshape::daemon::to_proto(direct.result.solution, &expected);
  EXPECT_EQ(response.solution().SerializeAsString(), expected.SerializeAsString());
}

TEST_F(GeometryEngineRpc, ACancelledLargeDeconstructionStops) {
  v1::DeconstructRequest request;
  *request.mutable_polygon() = read_exact_polygon(large_coast());
  request.mutable_radius()->set_rational("1/100");
  request.mutable_tolerance()->set_rational("1/200"); // eps = r / 2, delta = eps / 8
  grpc::ClientContext ctx;
  v1::DeconstructResponse response;
  auto call =
      std::async(std::launch::async, [&] { return stub_->Deconstruct(&ctx, request, &response); });
  std::this_thread::sleep_for(200ms);
  ctx.TryCancel();
  const grpc::Status status = call.get();
  // Either it finished within 200 ms or it was cancelled; both are correct answers.
  if (!status.ok()) {
    EXPECT_EQ(status.error_code(), grpc::StatusCode::CANCELLED);
  }
  // The worker is free again: the pool drains (a job that ignored the cancel would hang here).
  server_->shutdown();
}

} // namespace

namespace {

TEST_F(GeometryEngineRpc, IncludeOffsetReturnsSegmentsAndArcs) {
  // r <= eps: YES with P = Q, so offset(P, 1) of the 10 x 10 square is known in closed form:
  // four edges moved out by 1 and four quarter circles of radius 1 around the corners.
  v1::DeconstructRequest request;
  auto* ring = request.mutable_polygon()->add_polygons()->mutable_outer();
  for (auto [x, y] : {std::pair{0, 0}, {10, 0}, {10, 10}, {0, 10}}) {
    auto* p = ring->add_exact_points();
    p->set_x(std::to_string(x));
    p->set_y(std::to_string(y));
  }
  request.mutable_radius()->set_value(1);
  request.mutable_tolerance()->set_value(1);
  request.set_include_offset(true);
  grpc::ClientContext ctx;
  v1::DeconstructResponse response;
  const grpc::Status status = stub_->Deconstruct(&ctx, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_EQ(response.answer(), v1::ANSWER_YES);
  ASSERT_EQ(response.solution_offset().polygons_size(), 1);
  const double tolerance = response.solution_offset().max_error();
  EXPECT_GT(tolerance, 0.0);
  EXPECT_LE(tolerance, 0.01);
  int arcs = 0;
  int segments = 0;
  for (const auto& piece : response.solution_offset().polygons(0).outer().pieces()) {
    if (piece.has_arc()) {
      ++arcs;
      const auto& arc = piece.arc();
      EXPECT_EQ(arc.radius(), 1.0);
      const bool corner = (arc.center().x() == 0 || arc.center().x() == 10) &&
                          (arc.center().y() == 0 || arc.center().y() == 10);
      EXPECT_TRUE(corner) << arc.center().x() << " " << arc.center().y();
      EXPECT_NEAR(
          std::hypot(arc.start().x() - arc.center().x(), arc.start().y() - arc.center().y()), 1.0,
          tolerance);
    } else {
      ++segments;
      // Each straight piece lies on a line at distance 1 outside the square.
      const auto& s = piece.segment();
      const bool on_side =
          (std::abs(s.start().y() + 1) <= tolerance && std::abs(s.end().y() + 1) <= tolerance) ||
          (std::abs(s.start().y() - 11) <= tolerance && std::abs(s.end().y() - 11) <= tolerance) ||
          (std::abs(s.start().x() + 1) <= tolerance && std::abs(s.end().x() + 1) <= tolerance) ||
          (std::abs(s.start().x() - 11) <= tolerance && std::abs(s.end().x() - 11) <= tolerance);
      EXPECT_TRUE(on_side);
    }
  }
  EXPECT_EQ(arcs, 4);
  EXPECT_EQ(segments, 4);
}

} // namespace

namespace {

TEST_F(GeometryEngineRpc, SearchToleranceEqualsTheCoreSearch) {
  v1::SearchToleranceRequest request;
  *request.mutable_polygon() = read_exact_polygon(coast());
  request.mutable_radius()->set_rational("10");
  request.mutable_width()->set_rational("1/4");
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + 120s);
  auto stream = stub_->SearchTolerance(&ctx, request);
  v1::SearchToleranceResponse message;
  v1::SearchToleranceResult result;
  int results = 0;
  while (stream->Read(&message)) {
    if (message.has_result()) {
      result = message.result();
      ++results;
    }
  }
  const grpc::Status status = stream->Finish();
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_EQ(results, 1);

  const penshape::daemon::Limits limits;
  const penshape::PolygonSet q =
      penshape::daemon::polygon_set_from_proto(request.polygon(), "polygon", limits);
  const auto direct =
      penshape::search_tolerance(penshape::make_decider(q, penshape::EngineKind::kFast),
                                 penshape::Rational(10), penshape::Rational(1, 4));
  EXPECT_EQ(result.lower().rational(), direct.eps_low.get_str(10));
  EXPECT_EQ(result.upper().rational(), direct.eps_high.get_str(10));
  EXPECT_EQ(result.params().tolerance().rational(), direct.solution.params.tolerance.get_str(10));
  // The interval is as narrow as asked and the solution is certified at its upper side or above.
  EXPECT_LE(
      penshape::Rational(result.upper().rational()) - penshape::Rational(result.lower().rational()),
      penshape::Rational(1, 4));
  EXPECT_GT(result.solution().polygons_size(), 0);
  // The search's own account travels too (proto3 would default converged to false).
  ASSERT_TRUE(direct.converged);
  EXPECT_TRUE(result.converged());
  EXPECT_EQ(result.note(), direct.note);
  EXPECT_EQ(result.fallback_calls(), direct.fallback_calls);
  EXPECT_GE(result.decider_calls(), 1U);
}

TEST_F(GeometryEngineRpc, ACancelledSuggestRadiusStopsPromptly) {
  v1::SuggestRadiusRequest request;
  *request.mutable_polygon() = read_exact_polygon(large_coast());
  request.mutable_min_radius()->set_rational("1/1000");
  request.mutable_max_radius()->set_rational("1/10");
  request.set_samples(40);
  grpc::ClientContext ctx;
  auto stream = stub_->SuggestRadius(&ctx, request);
  std::this_thread::sleep_for(300ms);
  ctx.TryCancel();
  v1::SuggestRadiusResponse message;
  while (stream->Read(&message)) {
  }
  const grpc::Status status = stream->Finish();
  EXPECT_EQ(status.error_code(), grpc::StatusCode::CANCELLED);
  // The search itself stopped: the workers drain (a search that ignored the cancel would keep the
  // pool busy for many seconds and this would hang).
  server_->shutdown();
}

} // namespace

#include "penshape/daemon/ink_analyzer.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace {

TEST(InkAnalyzerRpc, SubmitStrokeReturnsTheInkPolygon) {
  penshape::daemon::ServerOptions options;
  options.address = "unix-abstract:penshape-ink-test-" + std::to_string(::getpid());
  penshape::daemon::PenshapeServer server(
      options, {nullptr, nullptr, penshape::daemon::make_ink_analyzer()});
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  // A straight 10 mm stroke (100 units per mm) with a 1 mm pen: a 12 x 2 mm stadium.
  v1::SubmitStrokeRequest request;
  auto* tablet = request.mutable_stroke()->mutable_tablet();
  tablet->set_x_max(30000);
  tablet->set_y_max(30000);
  tablet->set_x_resolution(100);
  tablet->set_y_resolution(100);
  for (int i = 0; i <= 10; ++i) {
    auto* s = request.mutable_stroke()->add_samples();
    s->set_time_us(std::int64_t{i} * 1000);
    s->set_x(1000 + 100 * i);
    s->set_y(1000);
    s->set_tip(i < 10);
  }
  request.mutable_settings()->set_pen_radius_mm(1.0);
  grpc::ClientContext ctx;
  v1::SubmitStrokeResponse response;
  const grpc::Status status = live->SubmitStroke(&ctx, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.shape().kind(), v1::SHAPE_KIND_UNSPECIFIED); // no recognizer yet
  ASSERT_EQ(response.ink_polygon().polygons_size(), 1);
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const auto& p : response.ink_polygon().polygons(0).outer().points()) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
  const double error = 1.0 / 50; // InkOptions' default bound: radius / 50
  EXPECT_NEAR(x0, 9.0, error);
  EXPECT_NEAR(x1, 21.0, error);
  EXPECT_NEAR(y0, 9.0, error);
  EXPECT_NEAR(y1, 11.0, error);
}

// A straight stroke from (x0, y0) to (x1, y1) in mm (100 units per mm), starting at t0_us.
void add_line(v1::Stroke* stroke, double x0, double y0, double x1, double y1, std::int64_t t0_us) {
  auto* tablet = stroke->mutable_tablet();
  tablet->set_x_max(30000);
  tablet->set_y_max(30000);
  tablet->set_x_resolution(100);
  tablet->set_y_resolution(100);
  for (int i = 0; i <= 20; ++i) {
    auto* s = stroke->add_samples();
    s->set_time_us(t0_us + std::int64_t{i} * 5000);
    s->set_x(static_cast<std::int32_t>(std::lround(100 * (x0 + (x1 - x0) * i / 20.0))));
    s->set_y(static_cast<std::int32_t>(std::lround(100 * (y0 + (y1 - y0) * i / 20.0))));
    s->set_tip(true);
  }
}

TEST(RecognizeRpc, SeveralStrokesAreGroupedIntoOneArrow) {
  penshape::daemon::ServerOptions options;
  options.address = "unix-abstract:penshape-group-test-" + std::to_string(::getpid());
  penshape::daemon::PenshapeServer server(
      options, {nullptr, nullptr, penshape::daemon::make_recognizing_analyzer()});
  auto geometry = v1::Geometry::NewStub(
      grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  v1::RecognizeRequest request;
  add_line(request.add_strokes(), 20, 80, 90, 80, 0); // the shaft
  v1::Stroke* head = request.add_strokes();           // a "V" head, half a second later
  add_line(head, 76, 86, 90, 80, 600'000);
  add_line(head, 90, 80, 76, 74, 800'000);
  request.mutable_settings()->set_pen_radius_mm(0.5);
  {
    grpc::ClientContext ctx;
    v1::RecognizeResponse response;
    const grpc::Status status = geometry->Recognize(&ctx, request, &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
    ASSERT_EQ(response.groups_size(), 1);
    EXPECT_EQ(response.groups(0).shape().kind(), v1::SHAPE_KIND_ARROW);
    ASSERT_EQ(response.groups(0).strokes_size(), 2);
    EXPECT_EQ(response.groups(0).strokes(1), 1u);
  }
  request.mutable_grouping()->set_disabled(true);
  {
    grpc::ClientContext ctx;
    v1::RecognizeResponse response;
    ASSERT_TRUE(geometry->Recognize(&ctx, request, &response).ok());
    EXPECT_EQ(response.groups_size(), 2) << "grouping off: each stroke alone";
  }
  request.mutable_grouping()->set_max_strokes(9);
  {
    grpc::ClientContext ctx;
    v1::RecognizeResponse response;
    const grpc::Status status = geometry->Recognize(&ctx, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_NE(status.error_message().find("max_strokes"), std::string::npos);
  }
  request.clear_grouping();
  add_line(request.mutable_stroke(), 0, 0, 10, 0, 0);
  {
    grpc::ClientContext ctx;
    v1::RecognizeResponse response;
    EXPECT_EQ(geometry->Recognize(&ctx, request, &response).error_code(),
              grpc::StatusCode::INVALID_ARGUMENT);
  }
}

} // namespace
