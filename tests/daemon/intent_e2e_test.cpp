// Writing is left alone by the daemon: a generated note page (cursive words at ~5 mm with i-dots
// and t-bars, shapes of 20-60 mm between the lines, timed as a hand draws) through penshaped's
// server with the recognizing analyzer and a real gRPC client. SubmitStroke with a group_key (the
// grouping a tablet's live strokes and StreamSamples use) and Recognize answer writing strokes
// INTENT_WRITING and freeform, never grouped, while the shapes snap; snap_writing = true snaps
// writing again; a held stroke is drawing; snap_writing survives the config file and Config RPC.
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "fakes.hpp"
#include "generated_ink.hpp"
#include "penshape/daemon/config.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/v1/config.grpc.pb.h"
#include "penshape/v1/geometry.grpc.pb.h"
#include "penshape/v1/live.grpc.pb.h"

namespace {

namespace v1 = penshape::v1;
namespace d = penshape::daemon;
using penshape::test::ink::PageStroke;

// The page: two lines of writing, then the five shapes, then two more lines.
std::vector<PageStroke> page() { return penshape::test::ink::note_page(3, true); }

// A stroke of the test tablet (100 units per mm) along `points` (mm, seconds), tip up at the end.
v1::Stroke stroke_of(const penshape::test::ink::Points& points) {
  v1::Stroke out;
  penshape::TabletInfo tablet = penshape::testing::test_tablet();
  tablet.x_max = tablet.y_max = 30000; // the page is 205 mm wide
  d::to_proto(tablet, out.mutable_tablet());
  for (std::size_t i = 0; i <= points.size(); ++i) {
    const penshape::StrokePoint& p = points[std::min(i, points.size() - 1)];
    v1::PenSample* s = out.add_samples();
    const std::int64_t after = i < points.size() ? 0 : 5000; // tip up 5 ms after the last
    s->set_time_us(std::llround(p.t * 1e6) + 1000 + after);
    s->set_x(static_cast<std::int32_t>(std::lround(p.x * 100)));
    s->set_y(static_cast<std::int32_t>(std::lround(p.y * 100)));
    s->set_pressure(i < points.size() ? 500 : 0);
    s->set_in_range(true);
    s->set_tip(i < points.size());
  }
  return out;
}

struct Daemon {
  explicit Daemon(const std::string& config_text = "")
      : address("unix-abstract:penshape-intent-" + std::to_string(::getpid()) + "-" +
                std::to_string(++count)),
        server(options(address, config_text), {nullptr, nullptr, d::make_recognizing_analyzer()}),
        channel(grpc::CreateChannel(address, grpc::InsecureChannelCredentials())) {}
  static d::ServerOptions options(const std::string& address, const std::string& config_text) {
    d::ServerOptions o;
    o.address = address;
    o.config = d::parse_config(config_text, "test.conf");
    return o;
  }
  // Every stroke of `strokes` submitted in order with one group_key: the answers.
  std::vector<v1::SubmitStrokeResponse> submit_all(const std::vector<PageStroke>& strokes) {
    auto live = v1::Live::NewStub(channel);
    std::vector<v1::SubmitStrokeResponse> out;
    for (const PageStroke& s : strokes) {
      v1::SubmitStrokeRequest request;
      request.set_group_key("notes");
      *request.mutable_stroke() = stroke_of(s.points);
      grpc::ClientContext ctx;
      const grpc::Status status = live->SubmitStroke(&ctx, request, &out.emplace_back());
      EXPECT_TRUE(status.ok()) << status.error_message();
    }
    return out;
  }
  static inline std::atomic<int> count{0};
  std::string address;
  d::PenshapeServer server;
  std::shared_ptr<grpc::Channel> channel;
};

bool snapped(const v1::Shape& shape) {
  return shape.kind() != v1::SHAPE_KIND_NONE && shape.kind() != v1::SHAPE_KIND_UNSPECIFIED;
}

TEST(DaemonIntent, SubmittedWritingStaysAsDrawnAndShapesSnap) {
  const std::vector<PageStroke> strokes = page();
  Daemon daemon;
  const auto answers = daemon.submit_all(strokes);
  ASSERT_EQ(answers.size(), strokes.size());
  std::set<std::uint64_t> writing_ids;
  int writing = 0, decided_writing = 0, shapes = 0; // words, words decided writing
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    const v1::Shape& shape = answers[i].shape();
    if (shape.intent() == v1::INTENT_WRITING) {
      writing_ids.insert(answers[i].stroke_id());
      EXPECT_FALSE(snapped(shape)) << "stroke " << i << ": writing is never snapped";
      EXPECT_TRUE(answers[i].replaced_stroke_ids().empty()) << "stroke " << i;
      EXPECT_TRUE(answers[i].supersedes_shape_ids().empty()) << "stroke " << i;
    }
    EXPECT_GE(shape.writing_score(), 0.0);
    EXPECT_LE(shape.writing_score(), 1.0);
    if (strokes[i].writing) {
      if (strokes[i].points.size() <= 10) continue; // a dot or a t-bar
      ++writing;                                    // a cursive word
      decided_writing += shape.intent() == v1::INTENT_WRITING ? 1 : 0;
    } else {
      ++shapes;
      EXPECT_EQ(shape.intent(), v1::INTENT_DRAWING) << "shape " << i;
      EXPECT_TRUE(snapped(shape)) << "shape " << i << " kind " << shape.kind();
    }
  }
  ASSERT_EQ(shapes, 5);
  // Live, a stroke's context is the strokes before it only (a t-bar just after its word may be
  // decided drawing then: core's live figure); every word is writing.
  EXPECT_EQ(decided_writing, writing);
  EXPECT_GT(writing, 20);
  for (const auto& a : answers) { // grouping never joins writing into a shape
    for (const std::uint64_t id : a.replaced_stroke_ids()) EXPECT_EQ(writing_ids.count(id), 0U);
  }
}

TEST(DaemonIntent, SnapWritingSnapsWritingAgain) {
  const std::vector<PageStroke> strokes = page();
  Daemon daemon("snap_writing = true\n");
  const auto answers = daemon.submit_all(strokes);
  ASSERT_EQ(answers.size(), strokes.size());
  int writing_snapped = 0;
  for (const auto& a : answers) {
    if (a.shape().intent() == v1::INTENT_WRITING && snapped(a.shape())) ++writing_snapped;
  }
  EXPECT_GT(writing_snapped, 0) << "t-bars are segments once writing is recognized";
}

TEST(DaemonIntent, RecognizeAnswersCarryTheIntent) {
  const std::vector<PageStroke> strokes = page();
  ASSERT_LE(strokes.size(), 64U);
  Daemon daemon;
  v1::RecognizeRequest request;
  for (const PageStroke& s : strokes) *request.add_strokes() = stroke_of(s.points);
  v1::RecognizeResponse response;
  grpc::ClientContext ctx;
  const grpc::Status status =
      v1::Geometry::NewStub(daemon.channel)->Recognize(&ctx, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  int shapes_snapped = 0;
  for (const v1::RecognizedGroup& g : response.groups()) {
    ASSERT_FALSE(g.strokes().empty());
    bool any_writing = false;
    for (const std::uint32_t i : g.strokes()) any_writing |= strokes.at(i).writing;
    if (g.shape().intent() == v1::INTENT_WRITING) {
      EXPECT_FALSE(snapped(g.shape()));
      EXPECT_EQ(g.strokes_size(), 1) << "writing is never grouped";
    } else {
      EXPECT_EQ(g.shape().intent(), v1::INTENT_DRAWING);
    }
    if (!any_writing && snapped(g.shape())) shapes_snapped += g.strokes_size();
    if (!any_writing) {
      EXPECT_EQ(g.shape().intent(), v1::INTENT_DRAWING);
    }
  }
  EXPECT_EQ(shapes_snapped, 5);
}

// A hold asks for a snap: the held stroke is drawing, even amid writing.
TEST(DaemonIntent, AHeldStrokeIsDrawing) {
  const std::vector<PageStroke> strokes = penshape::test::ink::note_page(2, false);
  auto analyzer = d::make_recognizing_analyzer();
  auto session = analyzer->group_session({}, {});
  ASSERT_NE(session, nullptr);
  std::uint64_t id = 0;
  const auto to_stroke = [&id](const penshape::test::ink::Points& points) {
    return penshape::Stroke{++id, penshape::testing::test_tablet(),
                            d::stroke_from_proto(stroke_of(points), "s", {}, true).samples};
  };
  for (const PageStroke& s : strokes) (void)session->add(to_stroke(s.points), true, {});
  // A 3 mm bar like the t-bars around it.
  double t = strokes.back().points.back().t + 0.3;
  const auto bar = penshape::test::ink::traced({{150, 45}, {153, 45.2}}, t);
  const penshape::Stroke stroke = to_stroke(bar);
  const auto copy = session->clone();
  const auto plain = copy->add(stroke, true, {});
  const auto held = session->add_held(stroke, {}, {});
  EXPECT_EQ(held.analysis.shape.intent(), v1::INTENT_DRAWING);
  EXPECT_EQ(held.analysis.shape.kind(), v1::SHAPE_KIND_SEGMENT);
  if (plain.analysis.shape.intent() == v1::INTENT_WRITING) {
    EXPECT_EQ(plain.analysis.shape.kind(), v1::SHAPE_KIND_NONE);
  }
}

TEST(DaemonIntent, SnapWritingConfigRoundTrip) {
  EXPECT_FALSE(d::parse_config("", "a.conf").settings.snap_writing) << "off by default";
  EXPECT_TRUE(d::parse_config("snap_writing = true\n", "a.conf").settings.snap_writing);
  const d::DaemonConfig device =
      d::parse_config("[device.\"28bd:0905\"]\nsnap_writing = true\n", "a.conf");
  EXPECT_EQ(device.device_settings.at("28bd:0905").snap_writing, true);
  try {
    (void)d::parse_config("snap_writing = \"sometimes\"\n", "a.conf");
    ADD_FAILURE() << "a bad value is refused";
  } catch (const d::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("snap_writing"), std::string::npos) << e.what();
  }
  Daemon daemon;
  auto config = v1::Config::NewStub(daemon.channel);
  v1::SetSettingsRequest request;
  request.set_device_key("28bd:0905");
  request.mutable_settings()->set_snap_writing(true);
  v1::SettingsResponse response;
  grpc::ClientContext set_ctx;
  ASSERT_TRUE(config->SetSettings(&set_ctx, request, &response).ok());
  EXPECT_TRUE(response.effective().snap_writing());
  grpc::ClientContext get_ctx;
  ASSERT_TRUE(config->GetSettings(&get_ctx, v1::GetSettingsRequest{}, &response).ok());
  EXPECT_FALSE(response.effective().snap_writing()) << "the defaults stay";
}

} // namespace
