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
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "penshape/daemon/device_manager_source.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/v1/live.grpc.pb.h"

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

} // namespace
