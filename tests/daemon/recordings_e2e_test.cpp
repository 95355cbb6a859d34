// Each bundled recording (recordings/*.hidrec) replayed through the daemon — the drivers' device
// manager, the segmenter, the geometry workers with the recognizing analyzer, the hub — reaches a
// real gRPC subscriber over a real unix socket as the strokes and shapes its .expected file lists.
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "penshape/daemon/device_manager_source.hpp"
#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/v1/live.grpc.pb.h"
#include "support/hausdorff_check.hpp"

namespace {

namespace fs = std::filesystem;
namespace v1 = penshape::v1;
using namespace std::chrono_literals;

std::vector<std::string> expected_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') out.push_back(line);
  }
  return out;
}

std::string kind_name(v1::ShapeKind kind) {
  static const std::map<v1::ShapeKind, std::string> names{
      {v1::SHAPE_KIND_NONE, "freeform"},
      {v1::SHAPE_KIND_SEGMENT, "segment"},
      {v1::SHAPE_KIND_POLYLINE, "polyline"},
      {v1::SHAPE_KIND_TRIANGLE, "triangle"},
      {v1::SHAPE_KIND_QUADRILATERAL, "quadrilateral"},
      {v1::SHAPE_KIND_RECTANGLE, "rectangle"},
      {v1::SHAPE_KIND_SQUARE, "square"},
      {v1::SHAPE_KIND_DIAMOND, "diamond"},
      {v1::SHAPE_KIND_REGULAR_POLYGON, "regular_polygon"},
      {v1::SHAPE_KIND_CIRCLE, "circle"},
      {v1::SHAPE_KIND_ELLIPSE, "ellipse"},
      {v1::SHAPE_KIND_ARC, "arc"}};
  const auto it = names.find(kind);
  return it == names.end() ? "unspecified" : it->second;
}

bool accepted(const std::string& line, const std::string& got) {
  if (line == "*") return true;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, '|');) {
    if (c == got) return true;
  }
  return false;
}

TEST(RecordingsE2E, EveryBundledRecordingGivesItsExpectedStrokesAndShapes) {
  std::size_t recordings = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PENSHAPE_SOURCE_DIR) / "recordings")) {
    if (entry.path().extension() != ".hidrec") continue;
    ++recordings;
    SCOPED_TRACE(entry.path().filename().string());
    fs::path expected_path = entry.path();
    expected_path.replace_extension(".expected");
    const auto expected = expected_lines(expected_path);

    penshape::daemon::ServerOptions options;
    options.address = "unix-abstract:penshape-rec-e2e-" + std::to_string(::getpid()) + "-" +
                      std::to_string(recordings);
    options.config.limits.subscriber_queue_events = 1U << 16; // comparing streams, not slowness
    auto source = std::make_shared<penshape::daemon::DeviceManagerSource>(nullptr);
    penshape::daemon::PenshapeServer server(
        options, {source, nullptr, penshape::daemon::make_recognizing_analyzer()});
    auto channel = grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials());
    auto live = v1::Live::NewStub(channel);
    grpc::ClientContext ctx;
    ctx.set_deadline(std::chrono::system_clock::now() + 120s);
    auto reader = live->Subscribe(&ctx, v1::SubscribeRequest{});
    const auto until = std::chrono::steady_clock::now() + 30s;
    while (server.hub().subscriber_count() < 1 && std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(1ms);
    }
    ASSERT_EQ(server.hub().subscriber_count(), 1U);

    source->replay(penshape::drivers::load_recording_file(entry.path()),
                   penshape::drivers::ReplaySpeed::kAsFastAsPossible);
    std::vector<std::uint64_t> finished;
    std::map<std::uint64_t, std::string> shapes;
    v1::LiveEvent event;
    while (shapes.size() < expected.size() && reader->Read(&event)) {
      EXPECT_FALSE(event.has_dropped());
      if (event.has_stroke_finished()) {
        finished.push_back(event.stroke_finished().stroke().id());
        EXPECT_GT(event.stroke_finished().ink_polygon().polygons_size(), 0);
      }
      if (event.has_shape()) {
        const auto& s = event.shape();
        shapes[s.stroke_id()] = kind_name(s.shape().kind());
        if (s.shape().kind() != v1::SHAPE_KIND_NONE) {
          // A snap carries its certificate: bound <= tolerance.
          EXPECT_LE(s.shape().certificate().hausdorff_bound().approx(),
                    s.shape().certificate().tolerance().approx());
        }
      }
    }
    ASSERT_EQ(finished.size(), expected.size());
    // The geometry workers finish strokes in any order; ids follow the pen.
    std::sort(finished.begin(), finished.end());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      ASSERT_EQ(shapes.count(finished[i]), 1U) << "stroke " << i;
      EXPECT_TRUE(accepted(expected[i], shapes[finished[i]]))
          << "stroke " << i << ": got " << shapes[finished[i]] << ", expected " << expected[i];
    }
    ctx.TryCancel();
  }
  EXPECT_GE(recordings, 2U);
}

// A solution as sent, read without the API's input checks (a simplified P may be a curve: a ring
// of two points, or of zero area).
penshape::PolygonSet solution_from_proto(const v1::PolygonSet& set) {
  auto ring = [](const v1::Ring& r) {
    penshape::Ring out;
    for (const auto& p : r.exact_points()) {
      out.push_back({penshape::Rational(p.x()), penshape::Rational(p.y())});
    }
    return out;
  };
  penshape::PolygonSet out;
  for (const auto& polygon : set.polygons()) {
    penshape::PolygonWithHoles pw;
    pw.outer = ring(polygon.outer());
    for (const auto& hole : polygon.holes()) pw.holes.push_back(ring(hole));
    out.polygons.push_back(std::move(pw));
  }
  return out;
}

// With a subscriber that asks for deconstructions, every stroke of every bundled recording also
// gets its StrokeDeconstructed after its shape; each YES is checked by the tests' own sampling
// Hausdorff estimate (no engine code): H(offset(P, r), Q) <= the certified bound, within the
// estimate's error.
TEST(RecordingsE2E, EveryBundledStrokeIsDeconstructedAndEachYesHolds) {
  std::size_t recordings = 0;
  std::size_t yes = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PENSHAPE_SOURCE_DIR) / "recordings")) {
    if (entry.path().extension() != ".hidrec") continue;
    ++recordings;
    SCOPED_TRACE(entry.path().filename().string());
    penshape::daemon::ServerOptions options;
    options.address = "unix-abstract:penshape-rec-deconstruct-" + std::to_string(::getpid()) + "-" +
                      std::to_string(recordings);
    options.config.limits.subscriber_queue_events = 1U << 16;
    auto source = std::make_shared<penshape::daemon::DeviceManagerSource>(nullptr);
    penshape::daemon::PenshapeServer server(options,
                                            {source, penshape::daemon::make_core_geometry_backend(),
                                             penshape::daemon::make_recognizing_analyzer()});
    auto live =
        v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
    grpc::ClientContext ctx;
    ctx.set_deadline(std::chrono::system_clock::now() + 300s);
    v1::SubscribeRequest request;
    request.set_include_deconstruction(true);
    auto reader = live->Subscribe(&ctx, request);
    const auto until = std::chrono::steady_clock::now() + 30s;
    while (server.hub().subscriber_count() < 1 && std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(1ms);
    }
    ASSERT_EQ(server.hub().subscriber_count(), 1U);
    const auto recording = penshape::drivers::load_recording_file(entry.path());
    source->replay(recording, penshape::drivers::ReplaySpeed::kAsFastAsPossible);
    fs::path expected_path = entry.path();
    expected_path.replace_extension(".expected");
    const std::size_t strokes = expected_lines(expected_path).size();

    std::map<std::uint64_t, v1::PolygonSet> ink;
    std::set<std::uint64_t> shaped;
    std::size_t deconstructed = 0;
    v1::LiveEvent event;
    const penshape::daemon::Limits limits;
    while (deconstructed < strokes && reader->Read(&event)) {
      if (event.has_stroke_finished()) {
        ink[event.stroke_finished().stroke().id()] = event.stroke_finished().ink_polygon();
      }
      if (event.has_shape()) shaped.insert(event.shape().stroke_id());
      if (!event.has_deconstructed()) continue;
      ++deconstructed;
      const v1::StrokeDeconstructed& d = event.deconstructed();
      SCOPED_TRACE("stroke " + std::to_string(d.stroke_id()));
      EXPECT_EQ(d.not_deconstructed(), "");
      EXPECT_EQ(shaped.count(d.stroke_id()), 1U) << "the shape comes first";
      if (d.result().answer() != v1::ANSWER_YES) continue;
      ++yes;
      const penshape::PolygonSet q =
          penshape::daemon::polygon_set_from_proto(ink.at(d.stroke_id()), "ink", limits);
      const penshape::PolygonSet p = solution_from_proto(d.result().solution());
      ASSERT_FALSE(p.polygons.empty());
      const double r = d.result().params().radius().approx();
      const double eps = d.result().params().tolerance().approx();
      const double bound = d.result().certificate().hausdorff_bound().approx();
      EXPECT_LE(bound, eps);
      EXPECT_TRUE(d.result().has_simplification());
      EXPECT_GT(d.result().solution_offset().polygons_size(), 0);
      const auto estimate = penshape::test::hausdorff_to_offset(
          penshape::test::region_skeleton(p), r, penshape::test::to_region_d(q), eps / 4);
      EXPECT_LE(estimate.value, bound + estimate.error);
    }
    EXPECT_EQ(deconstructed, strokes);
    ctx.TryCancel();
  }
  EXPECT_GE(recordings, 2U);
  EXPECT_GT(yes, 0U);
}

} // namespace
