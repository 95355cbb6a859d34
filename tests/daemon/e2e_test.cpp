// End to end: a real PenshapeServer on a real unix socket, real gRPC clients.
#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <map>
#include <set>
#include <thread>

#include "fakes.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/v1/config.grpc.pb.h"
#include "penshape/v1/geometry.grpc.pb.h"
#include "penshape/v1/live.grpc.pb.h"
#include "test_data.hpp"

namespace {

using namespace std::chrono_literals;
using penshape::daemon::PenshapeServer;
using penshape::daemon::ServerOptions;
using penshape::daemon::ServerParts;
using penshape::testing::FakeSampleSource;
namespace v1 = penshape::v1;

class TempDir {
 public:
  TempDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "penshaped-test-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp");
    path_ = pattern;
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
};

std::chrono::system_clock::time_point in(std::chrono::milliseconds d) {
  return std::chrono::system_clock::now() + d;
}

class DaemonE2E : public ::testing::Test {
 protected:
  std::string socket_path() const { return dir_.path() + "/penshape.sock"; }
  std::string address() const { return "unix:" + socket_path(); }

  void start(ServerParts parts = {}) {
    ServerOptions options;
    options.address = address();
    options.config = config_;
    server_ = std::make_unique<PenshapeServer>(options, std::move(parts));
  }
  std::shared_ptr<grpc::Channel> channel(const grpc::ChannelArguments& args = {}) const {
    return grpc::CreateCustomChannel(address(), grpc::InsecureChannelCredentials(), args);
  }
  void wait_for_subscribers(std::size_t n) const {
    const auto until = std::chrono::steady_clock::now() + 30s;
    while (server_->hub().subscriber_count() < n && std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(1ms);
    }
    ASSERT_EQ(server_->hub().subscriber_count(), n);
  }

  // A daemon fed by a fake source and the bounding-box analyzer, one subscriber (with or without
  // previews) already registered, and device "pen0" attached.
  struct LiveRig {
    std::shared_ptr<FakeSampleSource> source = std::make_shared<FakeSampleSource>();
    std::shared_ptr<penshape::testing::BoundingBoxAnalyzer> analyzer =
        std::make_shared<penshape::testing::BoundingBoxAnalyzer>();
    std::unique_ptr<v1::Live::Stub> live;
    grpc::ClientContext ctx;
    std::unique_ptr<grpc::ClientReader<v1::LiveEvent>> reader;
  };
  void start_live_rig(LiveRig& rig, bool previews) {
    start({rig.source, nullptr, rig.analyzer});
    rig.live = v1::Live::NewStub(channel());
    rig.ctx.set_deadline(in(30s));
    v1::SubscribeRequest request;
    request.set_include_previews(previews);
    rig.reader = rig.live->Subscribe(&rig.ctx, request);
    wait_for_subscribers(1);
    rig.source->attach("pen0");
  }

  TempDir dir_;
  penshape::daemon::DaemonConfig config_;
  std::unique_ptr<PenshapeServer> server_;
};

// grpc.health.v1.Health/Check through the generic stub; returns the serialized response.
std::string health_check(const std::shared_ptr<grpc::Channel>& channel, grpc::Status* status) {
  grpc::GenericStub generic(channel);
  grpc::ClientContext ctx;
  ctx.set_deadline(in(10s));
  grpc::Slice empty_message("");
  grpc::ByteBuffer request(&empty_message, 1);
  grpc::ByteBuffer reply;
  std::promise<grpc::Status> done;
  generic.UnaryCall(&ctx, "/grpc.health.v1.Health/Check", {}, &request, &reply,
                    [&](grpc::Status s) { done.set_value(std::move(s)); });
  *status = done.get_future().get();
  std::vector<grpc::Slice> slices;
  std::string bytes;
  if (status->ok() && reply.Dump(&slices).ok()) {
    for (const auto& s : slices) bytes.append(reinterpret_cast<const char*>(s.begin()), s.size());
  }
  return bytes;
}

TEST_F(DaemonE2E, HealthIsServingOnAnOwnerOnlySocketRemovedAtShutdown) {
  start();
  struct stat st {};
  ASSERT_EQ(::stat(socket_path().c_str(), &st), 0);
  EXPECT_TRUE(S_ISSOCK(st.st_mode));
  EXPECT_EQ(st.st_mode & 0777, 0600U);
  grpc::Status status;
  // HealthCheckResponse{status: SERVING(1)}: field 1, varint 1.
  EXPECT_EQ(health_check(channel(), &status), std::string("\x08\x01", 2));
  EXPECT_TRUE(status.ok()) << status.error_message();
  // A second daemon on the same socket is refused instead of stealing it.
  ServerOptions second;
  second.address = address();
  EXPECT_THROW(PenshapeServer{second}, std::runtime_error);
  server_->shutdown();
  EXPECT_FALSE(std::filesystem::exists(socket_path()));
}

// A source that cannot start (e.g. an unreadable recording).
class BrokenSource final : public penshape::daemon::SampleSource {
 public:
  void start(penshape::daemon::SampleSink& /*sink*/) override {
    throw std::runtime_error("cannot open the recording");
  }
  void stop() override {}
  [[nodiscard]] std::vector<penshape::daemon::DeviceDescriptor> devices() const override {
    return {};
  }
};

TEST_F(DaemonE2E, ASourceThatCannotStartLeavesNoSocket) {
  try {
    start({std::make_shared<BrokenSource>(), nullptr, nullptr});
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "cannot open the recording");
  }
  EXPECT_FALSE(std::filesystem::exists(socket_path()));
}

TEST_F(DaemonE2E, ConfigGetAndSetPerDevice) {
  config_.device_settings["056a:0010"].tolerance_fraction = 0.25;
  start();
  auto stub = v1::Config::NewStub(channel());
  auto get = [&](const std::string& key, v1::SettingsResponse* out) {
    grpc::ClientContext ctx;
    ctx.set_deadline(in(10s));
    v1::GetSettingsRequest request;
    request.set_device_key(key);
    return stub->GetSettings(&ctx, request, out);
  };
  v1::SettingsResponse defaults;
  ASSERT_TRUE(get("", &defaults).ok());
  EXPECT_EQ(defaults.effective().pen_radius_mm(), 1.0);
  EXPECT_FALSE(defaults.overridden());
  v1::SettingsResponse wacom;
  ASSERT_TRUE(get("056a:0010", &wacom).ok());
  EXPECT_TRUE(wacom.overridden());
  EXPECT_EQ(wacom.effective().tolerance_fraction(), 0.25);
  EXPECT_EQ(wacom.effective().pen_radius_mm(), 1.0); // inherited

  grpc::ClientContext ctx;
  v1::SetSettingsRequest set;
  set.set_device_key("056a:0010");
  set.mutable_settings()->set_pen_radius_mm(0.8);
  v1::SettingsResponse after;
  ASSERT_TRUE(stub->SetSettings(&ctx, set, &after).ok());
  EXPECT_EQ(after.effective().pen_radius_mm(), 0.8);
  EXPECT_EQ(after.effective().tolerance_fraction(), 0.25);
  ASSERT_TRUE(get("", &defaults).ok());
  EXPECT_EQ(defaults.effective().pen_radius_mm(), 1.0); // the defaults did not change
  EXPECT_EQ(server_->settings().effective("056a:0010").pen_radius_mm, 0.8);

  grpc::ClientContext list_ctx;
  v1::ListSettingsResponse list;
  ASSERT_TRUE(stub->ListSettings(&list_ctx, {}, &list).ok());
  ASSERT_EQ(list.settings_size(), 2);
  EXPECT_EQ(list.settings(1).device_key(), "056a:0010");

  grpc::ClientContext bad_ctx;
  set.mutable_settings()->set_pen_radius_mm(-1);
  const grpc::Status bad = stub->SetSettings(&bad_ctx, set, &after);
  EXPECT_EQ(bad.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad.error_message(), "settings.pen_radius_mm is -1, outside [0.05, 50]");
  v1::SettingsResponse unused;
  grpc::Status bad_key = get("56A:10", &unused);
  EXPECT_EQ(bad_key.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(bad_key.error_message().find("device_key"), std::string::npos);
}

// Reads a subscription's events until `stop` says enough; counts notices of drops.
struct Received {
  std::vector<v1::LiveEvent> events;
  std::uint64_t dropped = 0;
  grpc::Status status;
};

TEST_F(DaemonE2E, SubscribeDeliversTheSourcesStrokesWithTheirAnalysis) {
  auto source = std::make_shared<FakeSampleSource>();
  auto analyzer = std::make_shared<penshape::testing::BoundingBoxAnalyzer>();
  start({source, nullptr, analyzer});
  auto live = v1::Live::NewStub(channel());

  grpc::ClientContext watch_ctx;
  watch_ctx.set_deadline(in(30s));
  auto watch = live->WatchDevices(&watch_ctx, {});
  grpc::ClientContext ctx;
  ctx.set_deadline(in(30s));
  v1::SubscribeRequest request;
  request.set_include_samples(true);
  auto reader = live->Subscribe(&ctx, request);
  reader->WaitForInitialMetadata();
  wait_for_subscribers(2);

  source->attach("pen0");
  source->emit_stroke("pen0", 5);

  v1::LiveEvent event;
  ASSERT_TRUE(watch->Read(&event));
  EXPECT_EQ(event.device_attached().device().id(), "pen0");
  EXPECT_EQ(event.device_attached().device().settings_key(), "056a:0010");
  EXPECT_EQ(event.device_attached().device().tablet().x_max(), 20000);

  std::vector<v1::LiveEvent> got;
  while (got.size() < 8 && reader->Read(&event)) got.push_back(event);
  ASSERT_EQ(got.size(), 8U); // started, 5 samples, finished, shape
  EXPECT_EQ(got[0].stroke_started().stroke_id(), 1U);
  EXPECT_EQ(got[0].stroke_started().tablet().vendor_id(), 0x056aU);
  for (int i = 1; i <= 5; ++i) {
    ASSERT_TRUE(got[static_cast<std::size_t>(i)].has_samples());
    EXPECT_EQ(got[static_cast<std::size_t>(i)].samples().samples(0).x(), 1000 + 10 * (i - 1));
  }
  const v1::StrokeFinished& finished = got[6].stroke_finished();
  EXPECT_EQ(finished.stroke().samples_size(), 5);
  EXPECT_EQ(finished.not_analysed(), "");
  // The analyzer's box for x in 10.0..10.4 mm, y 20.0..20.04 mm, pen radius 1 mm.
  const auto& ink = finished.ink_polygon().polygons(0).outer();
  ASSERT_EQ(ink.points_size(), 4);
  EXPECT_DOUBLE_EQ(ink.points(0).x(), 9.0);
  EXPECT_DOUBLE_EQ(ink.points(2).x(), 11.4);
  EXPECT_EQ(got[7].shape().stroke_id(), 1U);
  EXPECT_EQ(got[7].shape().shape().kind(), v1::SHAPE_KIND_SEGMENT);
  for (std::size_t i = 1; i < got.size(); ++i) {
    EXPECT_GT(got[i].sequence(), got[i - 1].sequence());
    EXPECT_EQ(got[i].device_id(), "pen0");
  }

  grpc::ClientContext list_ctx;
  v1::ListDevicesResponse devices;
  ASSERT_TRUE(live->ListDevices(&list_ctx, {}, &devices).ok());
  ASSERT_EQ(devices.devices_size(), 1);
  EXPECT_EQ(devices.devices(0).source(), "/dev/fake-pen0");
  ctx.TryCancel();
  watch_ctx.TryCancel();
}

TEST_F(DaemonE2E, PreviewsArriveWhileAStrokeIsDrawn) {
  LiveRig rig;
  start_live_rig(rig, true);
  auto& analyzer = rig.analyzer;
  auto& reader = rig.reader;
  rig.source->emit_stroke("pen0", 40, 2ms); // the first sample already asks for a preview

  std::vector<double> confidences;
  bool shape = false;
  v1::LiveEvent event;
  while (!(shape && static_cast<int>(confidences.size()) == analyzer->previews.load()) &&
         reader->Read(&event)) {
    if (event.has_shape()) shape = true;
    if (!event.has_preview()) continue;
    EXPECT_EQ(event.preview().stroke_id(), 1U);
    ASSERT_EQ(event.preview().candidates_size(), 1);
    EXPECT_EQ(event.preview().candidates(0).kind(), v1::SHAPE_KIND_CIRCLE);
    confidences.push_back(event.preview().candidates(0).confidence());
  }
  ASSERT_TRUE(shape);
  ASSERT_GE(confidences.size(), 1U);
  EXPECT_EQ(confidences.front(), 1.0); // asked at the first sample
  for (std::size_t i = 1; i < confidences.size(); ++i) {
    EXPECT_GT(confidences[i], confidences[i - 1]); // later previews see more samples
  }
  EXPECT_LE(confidences.back(), 40.0);
  rig.ctx.TryCancel();
}

TEST_F(DaemonE2E, NoPreviewIsComputedWhenNoSubscriberAsksForPreviews) {
  LiveRig rig;
  start_live_rig(rig, false);
  rig.source->emit_stroke("pen0", 40, 2ms);
  v1::LiveEvent event;
  bool shape = false;
  while (!shape && rig.reader->Read(&event)) shape = event.has_shape();
  ASSERT_TRUE(shape);
  EXPECT_EQ(rig.analyzer->calls.load(), 1);
  EXPECT_EQ(rig.analyzer->previews.load(), 0);
  rig.ctx.TryCancel();
}

TEST_F(DaemonE2E, AHangingPreviewIsCancelledAndTheStrokesShapeStillArrives) {
  LiveRig rig;
  rig.analyzer->hold_previews = true;
  start_live_rig(rig, true);
  rig.source->emit_stroke("pen0", 40, 2ms); // a preview starts at the first sample, never ends
  v1::LiveEvent event;
  bool shape = false;
  while (!shape && rig.reader->Read(&event)) {
    EXPECT_FALSE(event.has_preview());
    shape = event.has_shape();
  }
  ASSERT_TRUE(shape);
  EXPECT_EQ(rig.analyzer->previews_started.load(), 1); // one at a time per device
  const auto until = std::chrono::steady_clock::now() + 10s;
  while (rig.analyzer->previews_cancelled.load() < 1 && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(1ms);
  }
  EXPECT_EQ(rig.analyzer->previews_cancelled.load(), 1); // the stroke's end (or staleness)
  rig.ctx.TryCancel();
}

// A preview still being computed when the pen lifts neither delays the stroke's shape nor is
// published once it is done: the shape supersedes it.
TEST_F(DaemonE2E, APreviewDoneAfterPenUpIsNotPublishedNorWaitedFor) {
  LiveRig rig;
  rig.analyzer->late_previews = true;
  start_live_rig(rig, true);
  rig.source->emit_stroke("pen0", 40, 2ms); // a preview starts at the first sample
  v1::LiveEvent event;
  bool shape = false;
  while (!shape && rig.reader->Read(&event)) shape = event.has_shape();
  ASSERT_TRUE(shape); // while the preview still runs
  EXPECT_EQ(rig.analyzer->previews_returned_late.load(), 0);
  rig.analyzer->release_previews = true;
  const auto until = std::chrono::steady_clock::now() + 10s;
  while (rig.analyzer->previews_returned_late.load() < 1 &&
         std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(1ms);
  }
  EXPECT_EQ(rig.analyzer->previews_returned_late.load(), 1);
  // Shutdown waits for the preview job, then ends the stream after every event published.
  std::thread stopper([&] { server_->shutdown(); });
  int previews = 0;
  while (rig.reader->Read(&event)) previews += event.has_preview() ? 1 : 0;
  stopper.join();
  EXPECT_EQ(previews, 0);
}

TEST_F(DaemonE2E, DeconstructionsFollowTheShapeOnlyForSubscribersThatAsk) {
  config_.settings.tolerance_fraction = 2; // eps >= r: the fake backend answers YES with P = Q
  auto source = std::make_shared<FakeSampleSource>();
  auto analyzer = std::make_shared<penshape::testing::BoundingBoxAnalyzer>();
  start({source, std::make_shared<penshape::testing::FakeGeometryBackend>(), analyzer});
  auto live = v1::Live::NewStub(channel());
  grpc::ClientContext asking_ctx;
  grpc::ClientContext plain_ctx;
  asking_ctx.set_deadline(in(30s));
  plain_ctx.set_deadline(in(30s));
  v1::SubscribeRequest asking_request;
  asking_request.set_include_deconstruction(true);
  auto asking = live->Subscribe(&asking_ctx, asking_request);
  auto plain = live->Subscribe(&plain_ctx, v1::SubscribeRequest{});
  wait_for_subscribers(2);
  source->attach("pen0");
  source->emit_stroke("pen0", 30);
  source->emit_stroke("pen0", 30);

  // The asking subscriber: per stroke finished, shape, then its deconstruction (P = Q here).
  std::map<std::uint64_t, v1::PolygonSet> ink;
  std::set<std::uint64_t> shaped;
  std::set<std::uint64_t> deconstructed;
  v1::LiveEvent event;
  while (deconstructed.size() < 2 && asking->Read(&event)) {
    if (event.has_stroke_finished()) {
      ink[event.stroke_finished().stroke().id()] = event.stroke_finished().ink_polygon();
    }
    if (event.has_shape()) shaped.insert(event.shape().stroke_id());
    if (!event.has_deconstructed()) continue;
    const v1::StrokeDeconstructed& d = event.deconstructed();
    EXPECT_EQ(d.not_deconstructed(), "");
    EXPECT_EQ(shaped.count(d.stroke_id()), 1U) << "the shape comes first";
    EXPECT_EQ(d.result().answer(), v1::ANSWER_YES);
    EXPECT_EQ(d.result().solution().polygons_size(), ink[d.stroke_id()].polygons_size());
    EXPECT_EQ(d.result().params().radius().approx(), 1.0); // the settings' r and eps = 2 r
    EXPECT_EQ(d.result().params().tolerance().approx(), 2.0);
    deconstructed.insert(d.stroke_id());
  }
  EXPECT_EQ(deconstructed, (std::set<std::uint64_t>{1, 2}));
  // The other one: both strokes' shapes and nothing else.
  std::size_t shapes = 0;
  while (shapes < 2 && plain->Read(&event)) {
    EXPECT_FALSE(event.has_deconstructed());
    if (event.has_shape()) ++shapes;
  }
  EXPECT_EQ(shapes, 2U);
  asking_ctx.TryCancel();
  plain_ctx.TryCancel();
}

TEST_F(DaemonE2E, SixtyFourClientsKeepUpWhileOneSubscriberNeverReads) {
  config_.limits.subscriber_queue_events = 4096;
  auto source = std::make_shared<FakeSampleSource>();
  start({source, nullptr, nullptr});
  constexpr int kClients = 64;
  constexpr int kStrokes = 500;          // 2 events each: started, finished
  constexpr int kSamplesPerStroke = 150; // ~3 KB per finished stroke

  // The slow one: a small queue and a transport that buffers little, and it never reads.
  grpc::ChannelArguments slow_args;
  slow_args.SetInt(GRPC_ARG_HTTP2_BDP_PROBE, 0);
  auto slow_live = v1::Live::NewStub(channel(slow_args));
  grpc::ClientContext slow_ctx;
  slow_ctx.set_deadline(in(120s));
  v1::SubscribeRequest slow_request;
  slow_request.set_max_queued_events(16);
  auto slow = slow_live->Subscribe(&slow_ctx, slow_request);

  std::vector<std::future<Received>> readers;
  readers.reserve(kClients);
  for (int c = 0; c < kClients; ++c) {
    readers.push_back(std::async(std::launch::async, [&] {
      auto live = v1::Live::NewStub(channel());
      grpc::ClientContext ctx;
      ctx.set_deadline(in(120s));
      auto reader = live->Subscribe(&ctx, {});
      Received r;
      v1::LiveEvent event;
      int finished = 0;
      while (finished < kStrokes && reader->Read(&event)) {
        if (event.has_dropped()) r.dropped += event.dropped().count();
        if (event.has_stroke_finished()) ++finished;
        r.events.push_back(std::move(event));
      }
      ctx.TryCancel();
      r.status = reader->Finish();
      return r;
    }));
  }
  wait_for_subscribers(kClients + 1);

  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < kStrokes; ++i) source->emit_stroke("pen0", kSamplesPerStroke);
  const auto produce_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("producer: %d strokes to %d subscribers in %.1f ms\n", kStrokes, kClients + 1,
              produce_ms);

  for (auto& f : readers) {
    Received r = f.get();
    EXPECT_EQ(r.dropped, 0U);
    ASSERT_EQ(r.events.size(), 2U * kStrokes);
    for (std::size_t i = 0; i < r.events.size(); ++i) {
      // In order, nothing missing: started(k), finished(k), started(k+1)...
      const std::uint64_t stroke = i / 2 + 1;
      if (i % 2 == 0) {
        EXPECT_EQ(r.events[i].stroke_started().stroke_id(), stroke);
      } else {
        EXPECT_EQ(r.events[i].stroke_finished().stroke().id(), stroke);
      }
    }
  }

  // Now the slow one reads: every event either arrived or was reported lost, and some were lost.
  std::uint64_t received = 0;
  std::uint64_t dropped = 0;
  std::uint64_t last_total = 0;
  v1::LiveEvent event;
  while (received + dropped < std::uint64_t{2} * kStrokes && slow->Read(&event)) {
    if (event.has_dropped()) {
      dropped += event.dropped().count();
      last_total = event.dropped().total();
    } else {
      ++received;
    }
  }
  EXPECT_EQ(received + dropped, 2U * kStrokes);
  EXPECT_GT(dropped, 0U);
  EXPECT_EQ(last_total, dropped);
  std::printf("slow subscriber: %llu received, %llu dropped (reported)\n",
              static_cast<unsigned long long>(received), static_cast<unsigned long long>(dropped));
  slow_ctx.TryCancel();
  (void)slow->Finish();
}

TEST_F(DaemonE2E, ShutdownDuringALiveStreamLosesNoFinishedStroke) {
  auto source = std::make_shared<FakeSampleSource>();
  auto analyzer = std::make_shared<penshape::testing::BoundingBoxAnalyzer>();
  start({source, nullptr, analyzer});
  auto live = v1::Live::NewStub(channel());
  grpc::ClientContext ctx;
  ctx.set_deadline(in(60s));
  auto reader = live->Subscribe(&ctx, {});
  wait_for_subscribers(1);

  // 20 samples of 200 µs per stroke; shutdown arrives in the middle of one, once some stroke has
  // finished (a fixed wait could end before the first on a loaded machine).
  source->run("pen0", 20, 200us);
  const auto patience = std::chrono::steady_clock::now() + 30s;
  while (source->finished() == 0 && std::chrono::steady_clock::now() < patience) {
    std::this_thread::sleep_for(5ms);
  }
  std::this_thread::sleep_for(20ms);
  std::thread stopper([&] { server_->shutdown(); });

  std::vector<std::uint64_t> finished;
  std::uint64_t shapes = 0;
  v1::LiveEvent event;
  while (reader->Read(&event)) {
    EXPECT_FALSE(event.has_dropped());
    if (event.has_stroke_finished()) finished.push_back(event.stroke_finished().stroke().id());
    if (event.has_shape()) ++shapes;
  }
  const grpc::Status status = reader->Finish();
  stopper.join();
  EXPECT_TRUE(status.ok()) << status.error_message(); // the stream ended, not broke
  ASSERT_TRUE(source->stopped());
  ASSERT_GT(source->finished(), 0U);
  ASSERT_EQ(finished.size(), source->finished());
  for (std::size_t i = 0; i < finished.size(); ++i) EXPECT_EQ(finished[i], i + 1);
  EXPECT_EQ(shapes, source->finished());
  EXPECT_FALSE(std::filesystem::exists(socket_path()));
}

v1::PolygonSet square(double side) {
  v1::PolygonSet set;
  auto* ring = set.add_polygons()->mutable_outer();
  for (auto [x, y] : {std::pair{0.0, 0.0}, {side, 0.0}, {side, side}, {0.0, side}}) {
    auto* p = ring->add_points();
    p->set_x(x);
    p->set_y(y);
  }
  return set;
}

TEST_F(DaemonE2E, BadRequestsGetInvalidArgumentNamingTheField) {
  start({nullptr, std::make_shared<penshape::testing::FakeGeometryBackend>(), nullptr});
  auto geometry = v1::Geometry::NewStub(channel());
  auto deconstruct = [&](const v1::DeconstructRequest& request) {
    grpc::ClientContext ctx;
    ctx.set_deadline(in(10s));
    v1::DeconstructResponse response;
    return geometry->Deconstruct(&ctx, request, &response);
  };
  v1::DeconstructRequest request;
  *request.mutable_polygon() = square(10);
  request.mutable_radius()->set_value(1);
  request.mutable_tolerance()->set_value(2);
  request.mutable_polygon()->mutable_polygons(0)->mutable_outer()->mutable_points(3)->set_x(NAN);
  grpc::Status s = deconstruct(request);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(s.error_message(), "polygon.polygons[0].outer.points[3].x is NaN");

  *request.mutable_polygon() = square(10);
  request.mutable_precision()->set_rational("2/0");
  s = deconstruct(request);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(s.error_message(), "precision.rational has a zero denominator");
  request.clear_precision();
  request.clear_tolerance();
  s = deconstruct(request);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(s.error_message(), "tolerance is missing");

  auto live = v1::Live::NewStub(channel());
  grpc::ClientContext ctx;
  v1::SubmitStrokeRequest submit;
  submit.mutable_stroke()->add_samples();
  v1::SubmitStrokeResponse submitted;
  s = live->SubmitStroke(&ctx, submit, &submitted);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(s.error_message(),
            "stroke.tablet.x_resolution must be > 0 (device units per millimetre)");

  // The searches validate their request, then say they are not in this build.
  grpc::ClientContext search_ctx;
  v1::SuggestRadiusRequest suggest;
  *suggest.mutable_polygon() = square(10);
  suggest.mutable_min_radius()->set_value(2);
  suggest.mutable_max_radius()->set_value(1);
  auto stream = geometry->SuggestRadius(&search_ctx, suggest);
  v1::SuggestRadiusResponse ignored;
  EXPECT_FALSE(stream->Read(&ignored));
  s = stream->Finish();
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(s.error_message(), "max_radius must be > min_radius");
  grpc::ClientContext search_ctx2;
  suggest.mutable_max_radius()->set_value(3);
  stream = geometry->SuggestRadius(&search_ctx2, suggest);
  EXPECT_FALSE(stream->Read(&ignored));
  s = stream->Finish();
  EXPECT_EQ(s.error_code(), grpc::StatusCode::UNIMPLEMENTED);
  EXPECT_NE(s.error_message().find("SuggestRadius"), std::string::npos);
}

TEST_F(DaemonE2E, DeconstructCarriesTheBackendsExactAnswer) {
  start({nullptr, std::make_shared<penshape::testing::FakeGeometryBackend>(), nullptr});
  auto geometry = v1::Geometry::NewStub(channel());
  v1::DeconstructRequest request;
  *request.mutable_polygon() = square(0.1);
  request.mutable_radius()->set_rational("1/4");
  request.mutable_tolerance()->set_value(0.5);
  request.set_engine(v1::ENGINE_REFERENCE);
  grpc::ClientContext ctx;
  v1::DeconstructResponse response;
  const grpc::Status s = geometry->Deconstruct(&ctx, request, &response);
  ASSERT_TRUE(s.ok()) << s.error_message();
  EXPECT_EQ(response.answer(), v1::ANSWER_YES);
  EXPECT_EQ(response.params().radius().rational(), "1/4");
  EXPECT_EQ(response.params().tolerance().rational(), "1/2");
  EXPECT_EQ(response.params().precision().rational(), "1/16");
  EXPECT_EQ(response.params().engine(), v1::ENGINE_REFERENCE);
  EXPECT_EQ(response.certificate().hausdorff_bound().rational(), "1/4");
  ASSERT_EQ(response.solution().polygons(0).outer().exact_points_size(), 4);
  // The double 0.1 went through exactly: 3602879701896397 / 2^55.
  EXPECT_EQ(response.solution().polygons(0).outer().exact_points(1).x(),
            "3602879701896397/36028797018963968");
  EXPECT_GE(response.timings().total_us(), response.timings().compute_us());

  request.set_include_offset(true);
  grpc::ClientContext ctx2;
  const grpc::Status offset = geometry->Deconstruct(&ctx2, request, &response);
  EXPECT_EQ(offset.error_code(), grpc::StatusCode::UNIMPLEMENTED);
  EXPECT_NE(offset.error_message().find("include_offset"), std::string::npos);
}

TEST_F(DaemonE2E, WithoutAnEngineDeconstructIsUnimplemented) {
  start();
  auto geometry = v1::Geometry::NewStub(channel());
  v1::DeconstructRequest request;
  *request.mutable_polygon() = square(1);
  request.mutable_radius()->set_value(1);
  request.mutable_tolerance()->set_value(1);
  grpc::ClientContext ctx;
  v1::DeconstructResponse response;
  const grpc::Status s = geometry->Deconstruct(&ctx, request, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::UNIMPLEMENTED);
  EXPECT_NE(s.error_message().find("PENSHAPE_DAEMON_WITH_ENGINE"), std::string::npos);
}

TEST_F(DaemonE2E, ACancelledLongCallStopsItsComputation) {
  auto backend = std::make_shared<penshape::testing::FakeGeometryBackend>();
  start({nullptr, backend, nullptr});
  auto geometry = v1::Geometry::NewStub(channel());
  v1::DeconstructRequest request;
  *request.mutable_polygon() = square(10);
  request.mutable_radius()->set_value(2); // r > eps: the fake runs until told to stop
  request.mutable_tolerance()->set_value(1);
  grpc::ClientContext ctx;
  v1::DeconstructResponse response;
  auto call = std::async(std::launch::async,
                         [&] { return geometry->Deconstruct(&ctx, request, &response); });
  backend->started.get_future().wait();
  ctx.TryCancel();
  EXPECT_EQ(call.get().error_code(), grpc::StatusCode::CANCELLED);
  // The computation itself stopped (not just the client's wait); the bound only guards a hang.
  EXPECT_EQ(backend->stopped.get_future().wait_for(30s), std::future_status::ready);
}

TEST_F(DaemonE2E, APassedDeadlineStopsItsComputation) {
  auto backend = std::make_shared<penshape::testing::FakeGeometryBackend>();
  start({nullptr, backend, nullptr});
  auto geometry = v1::Geometry::NewStub(channel());
  v1::DeconstructRequest request;
  *request.mutable_polygon() = square(10);
  request.mutable_radius()->set_value(2);
  request.mutable_tolerance()->set_value(1);
  grpc::ClientContext ctx;
  ctx.set_deadline(in(300ms));
  v1::DeconstructResponse response;
  EXPECT_EQ(geometry->Deconstruct(&ctx, request, &response).error_code(),
            grpc::StatusCode::DEADLINE_EXCEEDED);
  EXPECT_EQ(backend->stopped.get_future().wait_for(30s), std::future_status::ready);
}

TEST_F(DaemonE2E, SubscribersBeyondTheLimitAreRefused) {
  config_.limits.max_subscribers = 2;
  start();
  auto live = v1::Live::NewStub(channel());
  grpc::ClientContext a, b, c;
  auto ra = live->Subscribe(&a, {});
  auto rb = live->Subscribe(&b, {});
  wait_for_subscribers(2);
  auto rc = live->Subscribe(&c, {});
  v1::LiveEvent event;
  EXPECT_FALSE(rc->Read(&event));
  const grpc::Status s = rc->Finish();
  EXPECT_EQ(s.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  EXPECT_EQ(s.error_message(), "too many subscribers (limit max_subscribers = 2)");
  a.TryCancel();
  b.TryCancel();
}

TEST_F(DaemonE2E, OversizedMessagesAreRefused) {
  config_.limits.max_message_bytes = 4096;
  start({nullptr, std::make_shared<penshape::testing::FakeGeometryBackend>(), nullptr});
  auto geometry = v1::Geometry::NewStub(channel());
  v1::DeconstructRequest request;
  auto* ring = request.mutable_polygon()->add_polygons()->mutable_outer();
  for (int i = 0; i < 1000; ++i) {
    auto* p = ring->add_points();
    p->set_x(std::cos(i * 0.00628));
    p->set_y(std::sin(i * 0.00628));
  }
  request.mutable_radius()->set_value(1);
  request.mutable_tolerance()->set_value(1);
  grpc::ClientContext ctx;
  v1::DeconstructResponse response;
  EXPECT_EQ(geometry->Deconstruct(&ctx, request, &response).error_code(),
            grpc::StatusCode::RESOURCE_EXHAUSTED);
}

TEST_F(DaemonE2E, StreamSamplesCutsTheAppsStrokesAndAnswersEach) {
  auto analyzer = std::make_shared<penshape::testing::BoundingBoxAnalyzer>();
  start({nullptr, nullptr, analyzer});
  auto live = v1::Live::NewStub(channel());
  grpc::ClientContext ctx;
  ctx.set_deadline(in(30s));
  auto stream = live->StreamSamples(&ctx);
  v1::StreamSamplesRequest start_message;
  penshape::daemon::to_proto(penshape::testing::test_tablet(),
                             start_message.mutable_start()->mutable_tablet());
  ASSERT_TRUE(stream->Write(start_message));
  // Hover, a 3-sample stroke, hover, a stroke left down when the client finishes.
  v1::StreamSamplesRequest samples;
  const bool tips[] = {false, true, true, false, false, true, true};
  for (int i = 0; i < 7; ++i) {
    auto* s = samples.mutable_samples()->add_samples();
    s->set_time_us(std::int64_t{i} * 1000);
    s->set_x(100 * i);
    s->set_y(100);
    s->set_tip(tips[i]);
  }
  ASSERT_TRUE(stream->Write(samples));
  stream->WritesDone();
  std::vector<v1::LiveEvent> events;
  v1::LiveEvent event;
  while (stream->Read(&event)) events.push_back(event);
  ASSERT_TRUE(stream->Finish().ok());
  ASSERT_EQ(events.size(), 6U); // (started, finished, shape) twice
  EXPECT_TRUE(events[0].has_stroke_started());
  EXPECT_EQ(events[1].stroke_finished().stroke().samples_size(), 3); // tip down, down, up
  EXPECT_EQ(events[1].stroke_finished().stroke().samples(0).x(), 100);
  EXPECT_EQ(events[2].shape().shape().kind(), v1::SHAPE_KIND_SEGMENT);
  EXPECT_EQ(events[4].stroke_finished().stroke().samples_size(), 2);
  EXPECT_EQ(events[4].device_id(), "stream");
  EXPECT_EQ(analyzer->calls.load(), 2);
}

// An app streaming one stroke in four batches, 60 ms apart (longer than the preview interval).
std::vector<v1::LiveEvent> stream_batched_stroke(v1::Live::Stub& live, bool include_previews) {
  grpc::ClientContext ctx;
  ctx.set_deadline(in(30s));
  auto stream = live.StreamSamples(&ctx);
  v1::StreamSamplesRequest start_message;
  penshape::daemon::to_proto(penshape::testing::test_tablet(),
                             start_message.mutable_start()->mutable_tablet());
  start_message.mutable_start()->set_include_previews(include_previews);
  EXPECT_TRUE(stream->Write(start_message));
  for (int batch = 0; batch < 4; ++batch) {
    v1::StreamSamplesRequest samples;
    for (int i = 0; i < 5; ++i) {
      const int k = batch * 5 + i;
      auto* s = samples.mutable_samples()->add_samples();
      s->set_time_us(std::int64_t{k} * 1000);
      s->set_x(100 * k);
      s->set_y(100);
      s->set_tip(k < 19);
    }
    EXPECT_TRUE(stream->Write(samples));
    std::this_thread::sleep_for(60ms);
  }
  stream->WritesDone();
  std::vector<v1::LiveEvent> events;
  v1::LiveEvent event;
  while (stream->Read(&event)) events.push_back(event);
  EXPECT_TRUE(stream->Finish().ok());
  return events;
}

TEST_F(DaemonE2E, StreamSamplesSendsPreviewsOnlyWhenAsked) {
  auto analyzer = std::make_shared<penshape::testing::BoundingBoxAnalyzer>();
  start({nullptr, nullptr, analyzer});
  auto live = v1::Live::NewStub(channel());

  const auto plain = stream_batched_stroke(*live, false);
  for (const auto& e : plain) EXPECT_FALSE(e.has_preview());
  EXPECT_EQ(analyzer->previews.load(), 0);

  const auto events = stream_batched_stroke(*live, true);
  std::vector<double> seen; // the fake's confidence: samples seen by the preview
  bool shape = false;
  for (const auto& e : events) {
    if (e.has_shape()) shape = true;
    if (!e.has_preview()) continue;
    EXPECT_FALSE(shape) << "previews come before the stroke's shape";
    ASSERT_EQ(e.preview().candidates_size(), 1);
    seen.push_back(e.preview().candidates(0).confidence());
  }
  EXPECT_TRUE(shape);
  // Batches 1-3 end with the stroke in progress (the 4th ends it): previews after 5, 10 and 15
  // samples, the later two unless the server read their batches within 50 ms of the last preview.
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front(), 5.0); // the first batch always gets one
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_TRUE(seen[i] == 5.0 || seen[i] == 10.0 || seen[i] == 15.0) << seen[i];
    if (i > 0) {
      EXPECT_GT(seen[i], seen[i - 1]);
    }
  }
}

TEST_F(DaemonE2E, SubmitStrokeAnswersAndPublishes) {
  config_.device_settings["056a:0010"].pen_radius_mm = 2.0; // the test tablet's model
  auto analyzer = std::make_shared<penshape::testing::BoundingBoxAnalyzer>();
  start({nullptr, nullptr, analyzer});
  auto live = v1::Live::NewStub(channel());
  grpc::ClientContext sub_ctx;
  sub_ctx.set_deadline(in(30s));
  auto reader = live->Subscribe(&sub_ctx, {});
  wait_for_subscribers(1);
  v1::SubmitStrokeRequest request;
  penshape::daemon::to_proto(penshape::testing::test_tablet(),
                             request.mutable_stroke()->mutable_tablet());
  for (int i = 0; i < 3; ++i) {
    auto* s = request.mutable_stroke()->add_samples();
    s->set_time_us(i);
    s->set_x(500 + 100 * i);
    s->set_y(700);
    s->set_tip(i < 2);
  }
  request.mutable_settings()->set_pen_radius_mm(0.5);
  request.set_publish(true);
  grpc::ClientContext ctx;
  v1::SubmitStrokeResponse response;
  ASSERT_TRUE(live->SubmitStroke(&ctx, request, &response).ok());
  EXPECT_EQ(response.shape().kind(), v1::SHAPE_KIND_SEGMENT);
  // Box of x 5..7 mm, y 7 mm, grown by the requested 0.5 mm.
  EXPECT_DOUBLE_EQ(response.ink_polygon().polygons(0).outer().points(0).x(), 4.5);
  EXPECT_DOUBLE_EQ(response.ink_polygon().polygons(0).outer().points(2).y(), 7.5);
  v1::LiveEvent event;
  ASSERT_TRUE(reader->Read(&event));
  EXPECT_EQ(event.device_id(), "app");
  EXPECT_EQ(event.stroke_finished().stroke().id(), response.stroke_id());
  sub_ctx.TryCancel();

  // Without settings in the request, the tablet model's own settings apply (radius 2 mm).
  request.clear_settings();
  request.set_publish(false);
  grpc::ClientContext ctx2;
  ASSERT_TRUE(live->SubmitStroke(&ctx2, request, &response).ok());
  EXPECT_DOUBLE_EQ(response.ink_polygon().polygons(0).outer().points(0).x(), 3.0);
  EXPECT_DOUBLE_EQ(response.ink_polygon().polygons(0).outer().points(2).y(), 9.0);
}

} // namespace

// The drivers' device manager as the source: a recording (generated, in the Wacom PenPartner's
// protocol) replayed through the daemon reaches a subscriber as exactly the strokes the drivers'
// offline replay finds.
#include "penshape/daemon/device_manager_source.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"

namespace {

TEST_F(DaemonE2E, AReplayedRecordingReachesSubscribersAsTheDriversStrokes) {
  const auto recording = penshape::drivers::load_recording_file(
      (penshape::test::recordings_dir() / "generated-graphire.hidrec").string());
  const auto offline =
      penshape::drivers::replay(recording, penshape::drivers::ReplaySpeed::kAsFastAsPossible);
  ASSERT_GE(offline.strokes.size(), 3U);

  auto source = std::make_shared<penshape::daemon::DeviceManagerSource>(nullptr);
  // Room for the whole recording: this test compares streams, it is not about slow readers
  // (on a loaded machine the reader can fall a full default queue behind a fast replay).
  config_.limits.subscriber_queue_events = 1U << 16;
  start({source, nullptr, nullptr});
  auto live = v1::Live::NewStub(channel());
  grpc::ClientContext ctx;
  ctx.set_deadline(in(60s));
  v1::SubscribeRequest request;
  request.set_include_samples(true);
  auto reader = live->Subscribe(&ctx, request);
  grpc::ClientContext watch_ctx;
  watch_ctx.set_deadline(in(60s));
  auto watch = live->WatchDevices(&watch_ctx, {});
  wait_for_subscribers(2);

  source->replay(recording, penshape::drivers::ReplaySpeed::kAsFastAsPossible);
  v1::LiveEvent event;
  ASSERT_TRUE(watch->Read(&event));
  ASSERT_TRUE(event.has_device_attached());
  EXPECT_TRUE(event.device_attached().device().replay());
  EXPECT_EQ(event.device_attached().device().tablet().vendor_id(), 0x056aU);
  const std::string device = event.device_attached().device().id();
  // WatchDevices subscribes before it lists the devices, so an attach made in between comes twice.
  do {
    ASSERT_TRUE(watch->Read(&event));
  } while (event.has_device_attached() && event.device_attached().device().id() == device);
  EXPECT_EQ(event.device_detached().device_id(), device); // the recording ended

  std::vector<v1::Stroke> strokes;
  std::size_t samples = 0;
  std::set<std::uint64_t> started;
  while ((strokes.size() < offline.strokes.size() || samples < offline.samples.size()) &&
         reader->Read(&event)) {
    EXPECT_FALSE(event.has_dropped());
    EXPECT_EQ(event.device_id(), device);
    if (event.has_samples()) samples += static_cast<std::size_t>(event.samples().samples_size());
    if (event.has_stroke_started()) started.insert(event.stroke_started().stroke_id());
    if (event.has_stroke_finished()) strokes.push_back(event.stroke_finished().stroke());
  }
  ASSERT_EQ(strokes.size(), offline.strokes.size());
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(started.count(strokes[i].id()), 1U); // announced with the same id
    ASSERT_EQ(static_cast<std::size_t>(strokes[i].samples_size()),
              offline.strokes[i].samples.size());
    for (int k = 0; k < strokes[i].samples_size(); ++k) {
      const auto& a = strokes[i].samples(k);
      const auto& b = offline.strokes[i].samples[static_cast<std::size_t>(k)];
      EXPECT_EQ(a.x(), b.x);
      EXPECT_EQ(a.y(), b.y);
      EXPECT_EQ(a.tip(), b.tip);
      EXPECT_EQ(a.time_us(), b.time_us);
    }
  }
  EXPECT_EQ(samples, offline.samples.size()); // every decoded sample was published
  ctx.TryCancel();
  watch_ctx.TryCancel();
}

} // namespace
