// Hold to snap through the daemon: recordings made by `penshape synthesize-recording` from strokes
// with a hold appended (the pen within a fraction of a millimetre for 0.8 s), some with a drag or
// a tremor after it, and strokes without one, replayed through penshaped's device manager,
// segmenter, stroke strands and hub to a real gRPC subscriber over a unix socket, in each
// snap_trigger mode at 200 Hz and 1 kHz. Strokes drawn here run on a bare clone; real $1 strokes
// from ../shared/data/strokes/dollar1 run when the corpus is there.
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "dollar_xml.hpp"
#include "hold_recording.hpp"
#include "penshape/daemon/device_manager_source.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/v1/config.grpc.pb.h"
#include "penshape/v1/live.grpc.pb.h"
#include "test_data.hpp"

namespace {

namespace fs = std::filesystem;
namespace v1 = penshape::v1;
namespace d = penshape::daemon;
using namespace penshape::daemon_test;
using namespace std::chrono_literals;

// What one stroke got: its shape events before and after its StrokeFinished.
struct StrokeEvents {
  std::vector<v1::ShapeRecognized> before;
  std::vector<v1::ShapeRecognized> after;
  bool finished = false;
};

// Replays `recording` through an in-process penshaped with `trigger`; the events of each stroke,
// in drawing order. Stops once `strokes` strokes finished and the last one got its final shape
// (or after a minute).
std::vector<StrokeEvents> replay(const fs::path& recording, d::SnapTrigger trigger,
                                 std::size_t strokes, penshape::drivers::ReplaySpeed speed) {
  static int runs = 0;
  d::ServerOptions options;
  options.address = "unix-abstract:penshape-hold-e2e-" + std::to_string(::getpid()) + "-" +
                    std::to_string(++runs);
  options.config.limits.subscriber_queue_events = 1U << 16;
  options.config.settings.snap_trigger = trigger;
  auto source = std::make_shared<d::DeviceManagerSource>(nullptr);
  d::PenshapeServer server(options, {source, nullptr, d::make_recognizing_analyzer()});
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + 60s);
  auto reader = live->Subscribe(&ctx, v1::SubscribeRequest{});
  const auto until = std::chrono::steady_clock::now() + 30s;
  while (server.hub().subscriber_count() < 1 && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(1ms);
  }
  EXPECT_EQ(server.hub().subscriber_count(), 1U);
  source->replay(penshape::drivers::load_recording_file(recording), speed);
  std::vector<std::uint64_t> ids;
  std::map<std::uint64_t, StrokeEvents> by_id;
  std::size_t finished = 0;
  v1::LiveEvent event;
  while (reader->Read(&event)) {
    if (event.has_stroke_started()) ids.push_back(event.stroke_started().stroke_id());
    if (event.has_stroke_finished()) {
      by_id[event.stroke_finished().stroke().id()].finished = true;
      ++finished;
    }
    if (event.has_shape()) {
      const v1::ShapeRecognized& s = event.shape();
      StrokeEvents& e = by_id[s.stroke_id()];
      // A pen-up answer may come before its StrokeFinished (the shape does not wait for the ink
      // it did not read): it is after pen-up all the same.
      const bool pen_up = s.trigger() == v1::SHAPE_TRIGGER_PEN_UP;
      (e.finished || pen_up ? e.after : e.before).push_back(s);
    }
    const auto final_answer = [](const v1::ShapeRecognized& s) {
      return s.trigger() == v1::SHAPE_TRIGGER_PEN_UP || s.trigger() == v1::SHAPE_TRIGGER_RELEASE;
    };
    if (finished >= strokes && !ids.empty() &&
        std::any_of(by_id[ids.back()].after.begin(), by_id[ids.back()].after.end(), final_answer)) {
      break;
    }
  }
  ctx.TryCancel();
  std::vector<StrokeEvents> out;
  out.reserve(ids.size());
  for (const std::uint64_t id : ids) out.push_back(by_id[id]);
  EXPECT_EQ(out.size(), strokes);
  out.resize(strokes);
  return out;
}

bool is_round(v1::ShapeKind k) { return k == v1::SHAPE_KIND_CIRCLE || k == v1::SHAPE_KIND_ELLIPSE; }
bool is_box(v1::ShapeKind k) {
  return k == v1::SHAPE_KIND_RECTANGLE || k == v1::SHAPE_KIND_SQUARE ||
         k == v1::SHAPE_KIND_QUADRILATERAL;
}

const v1::ShapeRecognized* find(const std::vector<v1::ShapeRecognized>& events,
                                v1::ShapeTrigger trigger) {
  for (const auto& e : events) {
    if (e.trigger() == trigger) return &e;
  }
  return nullptr;
}

// The strokes drawn here (mm): what each is, and what a hold does to it.
enum class Plan { kHold, kNoHold, kHoldDrag, kHoldTremor };
struct DrawnStroke {
  TimedPath path;
  Plan plan;
  bool (*kind_ok)(v1::ShapeKind);
  double drag_x = 0; // the move after the hold, mm
  double drag_y = 0;
};

bool is_segment(v1::ShapeKind k) { return k == v1::SHAPE_KIND_SEGMENT; }

std::vector<DrawnStroke> drawn_strokes() {
  std::vector<DrawnStroke> out;
  auto add = [&](TimedPath p, Plan plan, bool (*ok)(v1::ShapeKind), double dx = 0, double dy = 0) {
    if (plan != Plan::kNoHold) then_hold(p, 0.8, 0.15);
    if (plan == Plan::kHoldTremor) then_hold(p, 0.3, 0.45);
    if (plan == Plan::kHoldDrag) then_move(p, dx, dy, 0.3);
    out.push_back({std::move(p), plan, ok, dx, dy});
  };
  const std::vector<std::pair<double, double>> box{{0, 0}, {44, 0}, {44, 28}, {0, 28}, {0, 0}};
  add(drawn_circle(18, 1.2), Plan::kHold, is_round);
  add(drawn_through(box, 120), Plan::kNoHold, is_box);
  add(drawn_through({{0, 0}, {40, 20}}, 100), Plan::kHoldDrag, is_segment, 0, 10);
  add(drawn_circle(15, 1.0), Plan::kNoHold, is_round);
  add(drawn_through(box, 120), Plan::kHoldTremor, is_box);
  // A hold in the middle of a stroke: the first leg snaps, the second leg drags its end.
  add(drawn_through({{0, 0}, {35, 0}}, 100), Plan::kHoldDrag, is_segment, 0, 25);
  add(drawn_circle(15, 1.0), Plan::kHoldDrag, is_round, 6, 0);   // outwards: the radius grows
  add(drawn_through(box, 120), Plan::kHoldDrag, is_box, -6, -4); // the corner moves out
  return out;
}

fs::path temp_dir() {
  fs::path dir = fs::temp_directory_path() / ("penshape-hold-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

fs::path drawn_recording(int rate_hz) {
  const fs::path dir = temp_dir();
  std::vector<TimedPath> paths;
  for (const DrawnStroke& s : drawn_strokes()) paths.push_back(s.path);
  write_strokes(dir / "drawn.jsonl", paths);
  fs::path out = dir / ("drawn-" + std::to_string(rate_hz) + ".hidrec");
  synthesize(dir / "drawn.jsonl", out, rate_hz, 1.0);
  return out;
}

// A held stroke: one HOLD of the right class before its StrokeFinished, certified on the drawn
// part; its RELEASE after it, moved as the drag says.
void check_held(const DrawnStroke& plan, const StrokeEvents& got) {
  ASSERT_EQ(!got.before.empty(), true) << "no HOLD before pen-up";
  const v1::ShapeRecognized& hold = got.before.front();
  EXPECT_EQ(hold.trigger(), v1::SHAPE_TRIGGER_HOLD);
  EXPECT_TRUE(plan.kind_ok(hold.shape().kind())) << v1::ShapeKind_Name(hold.shape().kind());
  EXPECT_EQ(hold.shape().certificate().scope(), "drawn_part");
  EXPECT_LE(hold.shape().certificate().hausdorff_bound().approx(),
            hold.shape().certificate().tolerance().approx());
  for (std::size_t i = 1; i < got.before.size(); ++i) {
    EXPECT_EQ(got.before[i].trigger(), v1::SHAPE_TRIGGER_FOLLOW);
    EXPECT_EQ(got.before[i].shape_id(), hold.shape_id());
  }
  ASSERT_EQ(got.after.size(), 1U);
  const v1::ShapeRecognized& release = got.after.front();
  EXPECT_EQ(release.trigger(), v1::SHAPE_TRIGGER_RELEASE);
  EXPECT_EQ(release.hold().held_shape_id(), hold.shape_id());
  const bool dragged = plan.plan == Plan::kHoldDrag;
  EXPECT_EQ(release.hold().adjusted(), dragged) << "tremor within hold_radius_mm is not a drag";
  if (!dragged) {
    EXPECT_EQ(release.shape_id(), hold.shape_id());
    EXPECT_EQ(release.supersedes_shape_ids_size(), 0);
    EXPECT_EQ(release.shape().SerializeAsString(), hold.shape().SerializeAsString());
    return;
  }
  EXPECT_NE(release.shape_id(), hold.shape_id());
  ASSERT_EQ(release.supersedes_shape_ids_size(), 1);
  EXPECT_EQ(release.supersedes_shape_ids(0), hold.shape_id());
  EXPECT_EQ(release.shape().certificate().scope(), "drawn_part+user_edit");
  const v1::Point& h = release.hold().hold_point();
  const v1::Point& p = release.hold().pen_point();
  EXPECT_NEAR(p.x() - h.x(), plan.drag_x, 0.3);
  EXPECT_NEAR(p.y() - h.y(), plan.drag_y, 0.3);
  const v1::Shape& a = hold.shape();
  const v1::Shape& b = release.shape();
  if (a.has_circle() && b.has_circle()) {
    EXPECT_NEAR(b.circle().radius() - a.circle().radius(), std::hypot(plan.drag_x, plan.drag_y),
                0.5);
  }
  if (a.kind() == v1::SHAPE_KIND_SEGMENT && b.kind() == v1::SHAPE_KIND_SEGMENT) {
    // The end where the pen held moved with the pen; the other stayed.
    const v1::Point& a1 = a.vertices().vertices(1);
    const v1::Point& b1 = b.vertices().vertices(1);
    EXPECT_NEAR(b1.x() - a1.x(), plan.drag_x, 0.3);
    EXPECT_NEAR(b1.y() - a1.y(), plan.drag_y, 0.3);
    EXPECT_EQ(b.vertices().vertices(0).SerializeAsString(),
              a.vertices().vertices(0).SerializeAsString());
  }
}

void check_drawn(const std::vector<StrokeEvents>& got, d::SnapTrigger trigger) {
  const std::vector<DrawnStroke> plans = drawn_strokes();
  ASSERT_EQ(got.size(), plans.size());
  for (std::size_t i = 0; i < plans.size(); ++i) {
    SCOPED_TRACE("stroke " + std::to_string(i));
    EXPECT_TRUE(got[i].finished);
    const bool held = plans[i].plan != Plan::kNoHold;
    if (trigger == d::SnapTrigger::kPenUp || (!held && trigger == d::SnapTrigger::kBoth)) {
      EXPECT_TRUE(got[i].before.empty()) << "a shape before pen-up";
      ASSERT_EQ(got[i].after.size(), 1U);
      EXPECT_EQ(got[i].after[0].trigger(), v1::SHAPE_TRIGGER_PEN_UP);
      if (!held) {
        EXPECT_TRUE(plans[i].kind_ok(got[i].after[0].shape().kind()))
            << v1::ShapeKind_Name(got[i].after[0].shape().kind());
      }
      continue;
    }
    if (!held) { // snap_trigger = hold: no hold, no snap
      EXPECT_TRUE(got[i].before.empty());
      EXPECT_TRUE(got[i].after.empty());
      continue;
    }
    check_held(plans[i], got[i]);
  }
}

class HoldSnapDrawn : public ::testing::TestWithParam<int> {};

TEST_P(HoldSnapDrawn, HeldStrokesSnapBeforePenUpInEveryMode) {
  const fs::path recording = drawn_recording(GetParam());
  for (const d::SnapTrigger trigger :
       {d::SnapTrigger::kHold, d::SnapTrigger::kBoth, d::SnapTrigger::kPenUp}) {
    SCOPED_TRACE(d::snap_trigger_name(trigger));
    check_drawn(replay(recording, trigger, drawn_strokes().size(),
                       penshape::drivers::ReplaySpeed::kAsFastAsPossible),
                trigger);
  }
}

INSTANTIATE_TEST_SUITE_P(Rates, HoldSnapDrawn, ::testing::Values(200, 1000));

// The events a StreamSamples stream (snap_trigger = hold in its StreamStart) sends back for
// `paths` (mm, seconds; one stroke each, a second apart), on a tablet of 100 units per mm.
std::vector<v1::LiveEvent> stream_strokes(const std::vector<TimedPath>& paths) {
  static int streams = 0;
  d::ServerOptions options;
  options.address = "unix-abstract:penshape-hold-stream-" + std::to_string(::getpid()) + "-" +
                    std::to_string(++streams);
  d::PenshapeServer server(options, {nullptr, nullptr, d::make_recognizing_analyzer()});
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + 60s);
  auto stream = live->StreamSamples(&ctx);
  v1::StreamSamplesRequest start;
  v1::TabletInfo* tablet = start.mutable_start()->mutable_tablet();
  tablet->set_x_resolution(100);
  tablet->set_y_resolution(100);
  tablet->set_x_max(100000);
  tablet->set_y_max(100000);
  start.mutable_start()->mutable_settings()->set_snap_trigger(v1::SNAP_TRIGGER_HOLD);
  EXPECT_TRUE(stream->Write(start));
  double t0 = 0;
  for (const TimedPath& path : paths) {
    v1::StreamSamplesRequest batch;
    for (const TimedPoint& p : path) {
      v1::PenSample* s = batch.mutable_samples()->add_samples();
      s->set_x(static_cast<std::int32_t>(std::lround((p.x + 50) * 100)));
      s->set_y(static_cast<std::int32_t>(std::lround((p.y + 50) * 100)));
      s->set_time_us(static_cast<std::int64_t>(std::llround((t0 + p.t) * 1e6)));
      s->set_tip(true);
      s->set_in_range(true);
    }
    v1::PenSample up = batch.samples().samples(batch.samples().samples_size() - 1);
    up.set_tip(false);
    up.set_time_us(up.time_us() + 2000);
    *batch.mutable_samples()->add_samples() = up;
    EXPECT_TRUE(stream->Write(batch));
    t0 += path.back().t + 0.3;
  }
  stream->WritesDone();
  std::vector<v1::LiveEvent> events;
  for (v1::LiveEvent e; stream->Read(&e);) events.push_back(e);
  EXPECT_TRUE(stream->Finish().ok());
  return events;
}

// An app's StreamSamples stream with snap_trigger = hold, at 500 Hz: a held circle dragged
// outwards snaps at the hold, follows the pen (updates at most one per 8 ms) and is released with
// the radius grown by the drag; a circle drawn without a hold gets no shape.
TEST(HoldSnapStream, AnAppsStreamHoldsFollowsAndReleases) {
  TimedPath held = drawn_circle(15, 1.0);
  then_hold(held, 0.8, 0.15);
  then_move(held, 6, 0, 0.3);
  const std::vector<v1::LiveEvent> events = stream_strokes({held, drawn_circle(15, 1.0)});
  std::vector<std::uint64_t> finished;
  std::vector<v1::ShapeRecognized> shapes;
  std::size_t hold_at = 0, first_finish_at = 0;
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (events[i].has_stroke_finished()) {
      if (finished.empty()) first_finish_at = i;
      finished.push_back(events[i].stroke_finished().stroke().id());
    }
    if (!events[i].has_shape()) continue;
    if (events[i].shape().trigger() == v1::SHAPE_TRIGGER_HOLD) hold_at = i;
    shapes.push_back(events[i].shape());
  }
  ASSERT_EQ(finished.size(), 2U);
  ASSERT_GE(shapes.size(), 3U);
  EXPECT_LT(hold_at, first_finish_at) << "the hold snap comes before pen-up";
  const v1::ShapeRecognized& hold = shapes.front();
  EXPECT_EQ(hold.trigger(), v1::SHAPE_TRIGGER_HOLD);
  EXPECT_TRUE(is_round(hold.shape().kind())) << v1::ShapeKind_Name(hold.shape().kind());
  std::size_t follows = 0;
  for (const auto& s : shapes) {
    EXPECT_EQ(s.stroke_id(), finished[0]) << "the stroke without a hold gets no shape";
    if (s.trigger() != v1::SHAPE_TRIGGER_FOLLOW) continue;
    ++follows;
    EXPECT_EQ(s.shape_id(), hold.shape_id());
  }
  EXPECT_GE(follows, 5U);
  EXPECT_LE(follows, 300U / 8 + 2) << "at most one update per 8 ms of a 300 ms drag";
  const v1::ShapeRecognized& release = shapes.back();
  EXPECT_EQ(release.trigger(), v1::SHAPE_TRIGGER_RELEASE);
  EXPECT_TRUE(release.hold().adjusted());
  ASSERT_EQ(release.supersedes_shape_ids_size(), 1);
  EXPECT_EQ(release.supersedes_shape_ids(0), hold.shape_id());
  if (hold.shape().has_circle() && release.shape().has_circle()) {
    EXPECT_NEAR(release.shape().circle().radius() - hold.shape().circle().radius(), 6, 0.5);
  }
}

// Grouping included: three sides of a rectangle drawn without a hold (snap_trigger = hold: no
// shape for them), the fourth held: the hold snaps the rectangle of all four strokes at once.
TEST(HoldSnapStream, AHoldCompletesAShapeWithTheStrokesBeforeIt) {
  std::vector<TimedPath> sides;
  const std::vector<std::pair<double, double>> corners{{0, 0}, {40, 0}, {40, 25}, {0, 25}, {0, 0}};
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    sides.push_back(drawn_through({corners[k], corners[k + 1]}, 150));
  }
  then_hold(sides.back(), 0.8, 0.15);
  const std::vector<v1::LiveEvent> events = stream_strokes(sides);
  std::vector<std::uint64_t> finished;
  std::vector<v1::ShapeRecognized> shapes;
  for (const v1::LiveEvent& e : events) {
    if (e.has_stroke_finished()) finished.push_back(e.stroke_finished().stroke().id());
    if (e.has_shape()) shapes.push_back(e.shape());
  }
  ASSERT_EQ(finished.size(), 4U);
  ASSERT_EQ(shapes.size(), 2U) << "a HOLD and its RELEASE, nothing for the sides without a hold";
  EXPECT_EQ(shapes[0].trigger(), v1::SHAPE_TRIGGER_HOLD);
  EXPECT_TRUE(is_box(shapes[0].shape().kind())) << v1::ShapeKind_Name(shapes[0].shape().kind());
  EXPECT_EQ(std::vector<std::uint64_t>(shapes[0].replaced_stroke_ids().begin(),
                                       shapes[0].replaced_stroke_ids().end()),
            finished);
  EXPECT_EQ(shapes[1].trigger(), v1::SHAPE_TRIGGER_RELEASE);
  EXPECT_EQ(shapes[1].shape_id(), shapes[0].shape_id());
}

// At the tablet's own pace (a recording replayed as recorded, 1 kHz): after the hold the shape
// follows the pen while it is still down, FOLLOW updates between the HOLD and pen-up with the
// HOLD's shape_id, no more than one per 8 ms.
TEST(HoldSnapDrawnLive, TheHeldShapeFollowsThePenBeforePenUp) {
  std::vector<DrawnStroke> plans;
  for (const DrawnStroke& s : drawn_strokes()) {
    if (s.plan == Plan::kHoldDrag && plans.size() < 2) plans.push_back(s);
  }
  std::vector<TimedPath> paths;
  paths.reserve(plans.size());
  for (const DrawnStroke& s : plans) paths.push_back(s.path);
  const fs::path dir = temp_dir();
  write_strokes(dir / "follow.jsonl", paths);
  synthesize(dir / "follow.jsonl", dir / "follow.hidrec", 1000, 1.0);
  const auto got = replay(dir / "follow.hidrec", d::SnapTrigger::kBoth, plans.size(),
                          penshape::drivers::ReplaySpeed::kOriginal);
  for (std::size_t i = 0; i < plans.size(); ++i) {
    SCOPED_TRACE("stroke " + std::to_string(i));
    check_held(plans[i], got[i]);
    std::size_t follows = 0;
    for (const auto& e : got[i].before) follows += e.trigger() == v1::SHAPE_TRIGGER_FOLLOW ? 1 : 0;
    EXPECT_GE(follows, 5U);
    EXPECT_LE(follows, 300U / 8 + 2);
  }
}

// The Config RPC reads and changes the hold settings per device model; a bad value is
// INVALID_ARGUMENT naming the field, and changes nothing.
TEST(HoldConfigRpc, PerDeviceSettingsAndBadValues) {
  d::ServerOptions options;
  options.address = "unix-abstract:penshape-hold-config-" + std::to_string(::getpid());
  d::PenshapeServer server(options, {nullptr, nullptr, d::make_recognizing_analyzer()});
  auto config =
      v1::Config::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  auto set = [&](const v1::SetSettingsRequest& request, v1::SettingsResponse* out) {
    grpc::ClientContext ctx;
    return config->SetSettings(&ctx, request, out);
  };
  v1::SetSettingsRequest request;
  request.set_device_key("28bd:0905");
  request.mutable_settings()->set_snap_trigger(v1::SNAP_TRIGGER_HOLD);
  request.mutable_settings()->set_hold_ms(800);
  request.mutable_settings()->set_hold_radius_mm(0.5);
  v1::SettingsResponse response;
  ASSERT_TRUE(set(request, &response).ok());
  EXPECT_EQ(response.effective().snap_trigger(), v1::SNAP_TRIGGER_HOLD);
  EXPECT_EQ(response.effective().hold_ms(), 800U);
  EXPECT_EQ(response.effective().hold_radius_mm(), 0.5);
  v1::GetSettingsRequest defaults;
  grpc::ClientContext get_ctx;
  ASSERT_TRUE(config->GetSettings(&get_ctx, defaults, &response).ok());
  EXPECT_EQ(response.effective().snap_trigger(), v1::SNAP_TRIGGER_BOTH) << "the defaults stay";
  EXPECT_EQ(response.effective().hold_ms(), 500U);
  for (const auto& [field, bad] : std::vector<std::pair<std::string, v1::PenSettings>>{
           {"settings.snap_trigger",
            [] {
              v1::PenSettings p;
              p.set_snap_trigger(v1::SNAP_TRIGGER_UNSPECIFIED);
              return p;
            }()},
           {"settings.hold_ms",
            [] {
              v1::PenSettings p;
              p.set_hold_ms(20);
              return p;
            }()},
           {"settings.hold_radius_mm", [] {
              v1::PenSettings p;
              p.set_hold_radius_mm(-1);
              return p;
            }()}}) {
    v1::SetSettingsRequest wrong;
    wrong.set_device_key("28bd:0905");
    *wrong.mutable_settings() = bad;
    const grpc::Status status = set(wrong, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << field;
    EXPECT_NE(status.error_message().find(field), std::string::npos) << status.error_message();
  }
  v1::GetSettingsRequest device;
  device.set_device_key("28bd:0905");
  grpc::ClientContext again;
  ASSERT_TRUE(config->GetSettings(&again, device, &response).ok());
  EXPECT_EQ(response.effective().hold_ms(), 800U) << "a refused change changes nothing";
}

// A $1 gesture log's points (pixels, milliseconds) as a path from t = 0 (seconds).
TimedPath dollar_path(const fs::path& file) {
  TimedPath out;
  for (const penshape::StrokePoint& p : penshape::dollar::read_dollar_xml(file).points) {
    if (!out.empty() && p.t <= out.back().t) continue; // a repeated time
    out.push_back({p.x, p.y, p.t});
  }
  const double t0 = out.empty() ? 0 : out.front().t;
  for (TimedPoint& p : out) p.t -= t0;
  return out;
}

// Real strokes ($1 circles, rectangles, triangles of five writers), each with a hold appended
// (0.5 px of tremor: 0.1 mm at the recording's 0.2 mm per pixel): every stroke whose pen-up snap
// (the same stroke without the hold, snap_trigger pen_up) has the right class gets, with the
// hold, a HOLD of the right class before its StrokeFinished.
TEST(HoldSnapReal, HeldDollarStrokesSnapBeforePenUpWithTheirClass) {
  PENSHAPE_SHARED_OR_SKIP(root, "strokes/dollar1");
  std::vector<TimedPath> plain;
  std::vector<std::string> labels;
  for (const std::string subject : {"s02", "s03", "s04", "s05", "s06"}) {
    for (const std::string gesture : {"circle", "rectangle", "triangle"}) {
      const fs::path file = root / subject / "medium" / (gesture + "01.xml");
      if (!fs::exists(file)) continue;
      plain.push_back(dollar_path(file));
      labels.push_back(gesture);
    }
  }
  ASSERT_GE(plain.size(), 3U);
  std::vector<TimedPath> held = plain;
  for (TimedPath& p : held) then_hold(p, 0.8, 0.5);
  const fs::path dir = temp_dir();
  write_strokes(dir / "plain.jsonl", plain);
  write_strokes(dir / "held.jsonl", held);
  synthesize(dir / "plain.jsonl", dir / "plain.hidrec", 200, 0.2);
  synthesize(dir / "held.jsonl", dir / "held.hidrec", 200, 0.2);
  const auto fast = penshape::drivers::ReplaySpeed::kAsFastAsPossible;
  const auto at_pen_up = replay(dir / "plain.hidrec", d::SnapTrigger::kPenUp, plain.size(), fast);
  const auto at_hold = replay(dir / "held.hidrec", d::SnapTrigger::kBoth, held.size(), fast);
  auto right = [](const std::string& label, v1::ShapeKind k) {
    return label == "circle"      ? is_round(k)
           : label == "rectangle" ? is_box(k)
                                  : k == v1::SHAPE_KIND_TRIANGLE;
  };
  std::size_t right_at_pen_up = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    SCOPED_TRACE("stroke " + std::to_string(i) + " (" + labels[i] + ")");
    ASSERT_EQ(at_pen_up[i].after.size(), 1U);
    if (!right(labels[i], at_pen_up[i].after[0].shape().kind())) continue;
    ++right_at_pen_up;
    const v1::ShapeRecognized* hold = find(at_hold[i].before, v1::SHAPE_TRIGGER_HOLD);
    ASSERT_NE(hold, nullptr) << "no HOLD before pen-up";
    EXPECT_TRUE(right(labels[i], hold->shape().kind())) << v1::ShapeKind_Name(hold->shape().kind());
    ASSERT_EQ(at_hold[i].after.size(), 1U);
    EXPECT_EQ(at_hold[i].after[0].trigger(), v1::SHAPE_TRIGGER_RELEASE);
    EXPECT_FALSE(at_hold[i].after[0].hold().adjusted());
  }
  EXPECT_GE(right_at_pen_up, labels.size() / 2);
}

} // namespace
