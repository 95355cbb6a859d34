// Live grouping through the real daemon: strokes injected as a tablet's reader would (stroke
// started, samples, stroke finished) into penshaped with the recognizing analyzer, read by a real
// gRPC subscriber over a unix socket. A rectangle drawn side by side comes back as one rectangle
// whose event names the four strokes whose ink it replaces and the earlier answers it
// supersedes; strokes of two tablets never group; two rectangles drawn apart stay two; the config
// keys and the Config RPC change the grouping; a preview of the last side shows the rectangle.
// Checks are independent of the recognizer: the strokes drawn, the corners drawn, the ids seen.
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "drawn_rectangle.hpp"
#include "fakes.hpp"
#include "penshape/daemon/config.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/v1/config.grpc.pb.h"
#include "penshape/v1/live.grpc.pb.h"

namespace {

namespace v1 = penshape::v1;
using penshape::PointD;
using penshape::daemon_test::ids_of;
using penshape::daemon_test::is_rectangle;
using penshape::daemon_test::rectangle_sides;
using penshape::daemon_test::side;
using namespace std::chrono_literals;

// Draws strokes given in millimetres on attached test tablets (100 units per mm), with device
// times that run on by the pauses asked for.
class ScriptedSource final : public penshape::daemon::SampleSource {
 public:
  void start(penshape::daemon::SampleSink& sink) override { sink_ = &sink; }
  void stop() override {}
  [[nodiscard]] std::vector<penshape::daemon::DeviceDescriptor> devices() const override {
    return {};
  }
  void attach(const std::string& id) {
    sink_->device_attached({id, penshape::testing::test_tablet(), "/dev/scripted-" + id, false});
  }
  // One stroke along `mm` (5 ms between samples) after a pen-up pause; while `hold` returns true
  // the pen stays down on the last point (a sample every 5 ms, in real time). Returns its id.
  std::uint64_t draw(const std::string& device, const std::vector<PointD>& mm,
                     std::int64_t pause_us = 300'000, const std::function<bool()>& hold = {}) {
    penshape::Stroke stroke;
    stroke.id = ++next_id_;
    stroke.tablet = penshape::testing::test_tablet();
    std::int64_t& t = clock_us_[device];
    t += pause_us;
    sink_->stroke_started(device, stroke.id);
    auto emit = [&](PointD p, bool tip) {
      penshape::PenSample s;
      s.time_us = t += 5000;
      s.x = static_cast<std::int32_t>(std::lround(p.x * 100));
      s.y = static_cast<std::int32_t>(std::lround(p.y * 100));
      s.pressure = tip ? 500 : 0;
      s.in_range = true;
      s.tip = tip;
      sink_->sample(device, stroke.id, s);
      stroke.samples.push_back(s);
    };
    for (const PointD& p : mm) emit(p, true);
    while (hold && hold()) {
      emit(mm.back(), true);
      std::this_thread::sleep_for(5ms);
    }
    emit(mm.back(), false);
    sink_->stroke_finished(device, std::move(stroke));
    return next_id_;
  }

 private:
  penshape::daemon::SampleSink* sink_ = nullptr;
  std::uint64_t next_id_ = 0;
  std::map<std::string, std::int64_t> clock_us_;
};

// Every ShapeRecognized (and group preview) the subscriber reads, with its LiveEvent sequence.
class Collector {
 public:
  explicit Collector(const std::string& address, bool previews) {
    thread_ = std::thread([this, address, previews] {
      auto live =
          v1::Live::NewStub(grpc::CreateChannel(address, grpc::InsecureChannelCredentials()));
      v1::SubscribeRequest request;
      request.set_include_previews(previews);
      auto stream = live->Subscribe(&ctx_, request);
      v1::LiveEvent event;
      while (stream->Read(&event)) {
        std::lock_guard lock(mutex_);
        if (event.has_shape()) shapes_.push_back(event);
        if (event.has_preview() && event.preview().has_group()) groups_.push_back(event);
        changed_.notify_all();
      }
      (void)stream->Finish();
    });
  }
  ~Collector() {
    ctx_.TryCancel();
    thread_.join();
  }
  // Waits (up to 60 s) until `n` shape events were read; returns them all.
  std::vector<v1::LiveEvent> shapes(std::size_t n) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, 60s, [&] { return shapes_.size() >= n; });
    return shapes_;
  }
  [[nodiscard]] std::size_t group_previews() {
    std::lock_guard lock(mutex_);
    return groups_.size();
  }
  std::vector<v1::LiveEvent> group_preview_events() {
    std::lock_guard lock(mutex_);
    return groups_;
  }

 private:
  grpc::ClientContext ctx_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<v1::LiveEvent> shapes_;
  std::vector<v1::LiveEvent> groups_;
  std::thread thread_;
};

// A daemon with the recognizing analyzer, the scripted source and one subscriber.
struct Daemon {
  explicit Daemon(const std::string& config_text = "", bool previews = false)
      : address("unix-abstract:penshape-grouping-" + std::to_string(::getpid()) + "-" +
                std::to_string(++count)),
        source(std::make_shared<ScriptedSource>()),
        server(options(address, config_text),
               {source, nullptr, penshape::daemon::make_recognizing_analyzer()}) {
    collector = std::make_unique<Collector>(address, previews);
    const auto until = std::chrono::steady_clock::now() + 30s;
    while (server.hub().subscriber_count() < 1 && std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(1ms);
    }
  }
  static penshape::daemon::ServerOptions options(const std::string& address,
                                                 const std::string& config_text) {
    penshape::daemon::ServerOptions o;
    o.address = address;
    o.config = penshape::daemon::parse_config(config_text, "test.conf");
    o.config.limits.subscriber_queue_events = 1U << 16;
    return o;
  }
  std::vector<std::uint64_t> draw_rectangle(const std::string& device, double x0, double y0,
                                            double x1, double y1) {
    std::vector<std::uint64_t> ids;
    for (const auto& s : rectangle_sides(x0, y0, x1, y1)) ids.push_back(source->draw(device, s));
    return ids;
  }
  static inline std::atomic<int> count{0};
  std::string address;
  std::shared_ptr<ScriptedSource> source;
  penshape::daemon::PenshapeServer server;
  std::unique_ptr<Collector> collector;
};

// The strokes an answer covers: the ink it replaces, or just its own stroke when it is freeform.
std::set<std::uint64_t> covered(const v1::ShapeRecognized& s) {
  if (s.replaced_stroke_ids_size() == 0) return {s.stroke_id()};
  return {s.replaced_stroke_ids().begin(), s.replaced_stroke_ids().end()};
}

// Each answer's superseded answers are earlier answers of the same device, named by their
// shape_id and sequence, and together with the new stroke they cover exactly its strokes.
void expect_consistent_supersession(const std::vector<v1::LiveEvent>& events) {
  std::map<std::uint64_t, const v1::LiveEvent*> by_shape_id;
  for (const v1::LiveEvent& e : events) {
    const v1::ShapeRecognized& s = e.shape();
    SCOPED_TRACE("stroke " + std::to_string(s.stroke_id()));
    EXPECT_NE(s.shape_id(), 0U);
    EXPECT_EQ(by_shape_id.count(s.shape_id()), 0U) << "shape ids are unique";
    ASSERT_EQ(s.supersedes_shape_ids_size(), s.supersedes_sequences_size());
    std::set<std::uint64_t> union_of = {s.stroke_id()};
    for (int i = 0; i < s.supersedes_shape_ids_size(); ++i) {
      const auto it = by_shape_id.find(s.supersedes_shape_ids(i));
      ASSERT_NE(it, by_shape_id.end()) << "supersedes an answer published before it";
      EXPECT_EQ(it->second->device_id(), e.device_id());
      EXPECT_EQ(it->second->sequence(), s.supersedes_sequences(i));
      for (std::uint64_t id : covered(it->second->shape())) union_of.insert(id);
    }
    if (s.supersedes_shape_ids_size() > 0) {
      EXPECT_EQ(union_of, covered(s));
    }
    by_shape_id[s.shape_id()] = &e;
  }
}

TEST(LiveGrouping, RectangleInFourStrokesReplacesThemAndSupersedesTheEarlierAnswer) {
  Daemon d;
  d.source->attach("tablet");
  const auto ids = d.draw_rectangle("tablet", 20, 20, 80, 60);
  const auto events = d.collector->shapes(4);
  ASSERT_EQ(events.size(), 4U);
  expect_consistent_supersession(events);
  const v1::ShapeRecognized& last = events.back().shape();
  EXPECT_EQ(last.stroke_id(), ids.back());
  ASSERT_TRUE(is_rectangle(last.shape().kind())) << last.shape().kind();
  EXPECT_EQ(ids_of(last.replaced_stroke_ids()), ids);
  // The upgrade names what the first three strokes were, and nothing else.
  ASSERT_GE(last.supersedes_shape_ids_size(), 1);
  std::set<std::uint64_t> before;
  for (std::uint64_t sid : last.supersedes_shape_ids()) {
    for (const auto& e : events) {
      if (e.shape().shape_id() == sid) {
        for (auto id : covered(e.shape())) before.insert(id);
      }
    }
  }
  EXPECT_EQ(before, std::set<std::uint64_t>(ids.begin(), ids.end() - 1));
  // Its corners are the corners drawn (to within the pen's wobble and the gaps at the corners).
  const std::vector<PointD> drawn = {{20, 20}, {80, 20}, {80, 60}, {20, 60}};
  ASSERT_EQ(last.shape().vertices().vertices_size(), 4);
  for (const PointD& c : drawn) {
    double nearest = 1e9;
    for (const auto& v : last.shape().vertices().vertices()) {
      nearest = std::min(nearest, std::hypot(v.x() - c.x, v.y() - c.y));
    }
    EXPECT_LT(nearest, 1.5) << "corner " << c.x << "," << c.y;
  }
  EXPECT_LE(last.shape().certificate().hausdorff_bound().approx(),
            last.shape().certificate().tolerance().approx());
}

TEST(LiveGrouping, StrokesOfTwoTabletsNeverGroupTogether) {
  Daemon d;
  d.source->attach("a");
  d.source->attach("b");
  // The sides of one rectangle, alternately on two tablets at the same place.
  const auto sides = rectangle_sides(20, 20, 80, 60);
  std::map<std::uint64_t, std::string> device_of;
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const std::string device = i % 2 == 0 ? "a" : "b";
    device_of[d.source->draw(device, sides[i])] = device;
  }
  const auto events = d.collector->shapes(4);
  ASSERT_EQ(events.size(), 4U);
  expect_consistent_supersession(events);
  for (const auto& e : events) {
    EXPECT_FALSE(is_rectangle(e.shape().shape().kind()));
    for (std::uint64_t id : covered(e.shape())) EXPECT_EQ(device_of[id], e.device_id());
  }
}

TEST(LiveGrouping, TwoRectanglesDrawnApartStayTwo) {
  Daemon d;
  d.source->attach("tablet");
  const auto first = d.draw_rectangle("tablet", 20, 20, 60, 50);
  const auto second = d.draw_rectangle("tablet", 100, 20, 140, 50);
  const auto events = d.collector->shapes(8);
  ASSERT_EQ(events.size(), 8U);
  expect_consistent_supersession(events);
  EXPECT_EQ(ids_of(events[3].shape().replaced_stroke_ids()), first);
  EXPECT_EQ(ids_of(events[7].shape().replaced_stroke_ids()), second);
  EXPECT_TRUE(is_rectangle(events[7].shape().shape().kind()));
  for (const auto& e : events) {
    const auto c = covered(e.shape());
    const bool in_first =
        std::any_of(c.begin(), c.end(), [&](auto id) { return id <= first.back(); });
    const bool in_second =
        std::any_of(c.begin(), c.end(), [&](auto id) { return id > first.back(); });
    EXPECT_FALSE(in_first && in_second) << "stroke " << e.shape().stroke_id();
  }
}

// A long session: rectangles drawn in 4 sides still group after hundreds of unrelated strokes
// (short lines apart from each other, most within the pause window of the one before): one whose
// sides are strokes 254-257 (a grouping that started afresh after 256 strokes would split it),
// and one after 300 unrelated strokes. Each event names exactly its 4 strokes. The grouping keeps
// only the strokes its window can reach (the session's bound is checked in the analyzer's test).
TEST(LiveGrouping, RectanglesAfterHundredsOfStrokesStillGroup) {
  Daemon d;
  d.source->attach("tablet");
  auto unrelated = [&](int from, int to) {
    for (int i = from; i < to; ++i) {
      const int row = i / 20;
      const PointD o{10.0 * (i % 20), 10.0 * row};
      const PointD end = i % 2 == 0 ? PointD{o.x + 5, o.y} : PointD{o.x, o.y + 5};
      d.source->draw("tablet", side(o, end), i % 25 == 24 ? 3'000'000 : 300'000);
    }
  };
  unrelated(0, 253);
  const auto first = d.draw_rectangle("tablet", 250, 20, 310, 60);
  unrelated(253, 300);
  const auto second = d.draw_rectangle("tablet", 250, 80, 310, 120);
  const auto events = d.collector->shapes(308);
  ASSERT_EQ(events.size(), 308U);
  expect_consistent_supersession(events);
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (i == 256 || i == 307) continue;
    EXPECT_LE(covered(events[i].shape()).size(), 3U) << "event " << i;
  }
  for (const auto& [last, ids] :
       {std::pair{events[256].shape(), first}, {events[307].shape(), second}}) {
    EXPECT_EQ(last.stroke_id(), ids.back());
    EXPECT_TRUE(is_rectangle(last.shape().kind())) << last.shape().kind();
    EXPECT_EQ(ids_of(last.replaced_stroke_ids()), ids);
    EXPECT_FALSE(last.supersedes_shape_ids().empty());
  }
}

// No answer covers more than `max` strokes, and no rectangle covers four.
void expect_groups_of_at_most(const std::vector<v1::LiveEvent>& events, int max) {
  for (const auto& e : events) {
    EXPECT_LE(e.shape().replaced_stroke_ids_size(), max) << "stroke " << e.shape().stroke_id();
    EXPECT_TRUE(e.shape().supersedes_shape_ids().empty() || max > 1);
  }
}

TEST(LiveGrouping, ConfigKeysChangeTheGrouping) {
  {
    Daemon d("grouping = false\n");
    d.source->attach("tablet");
    d.draw_rectangle("tablet", 20, 20, 80, 60);
    const auto events = d.collector->shapes(4);
    ASSERT_EQ(events.size(), 4U);
    expect_groups_of_at_most(events, 1);
  }
  {
    Daemon d("group_max_strokes = 3\n");
    d.source->attach("tablet");
    d.draw_rectangle("tablet", 20, 20, 80, 60);
    const auto events = d.collector->shapes(4);
    ASSERT_EQ(events.size(), 4U);
    expect_groups_of_at_most(events, 3);
  }
  {
    // A pause longer than the window between the third and fourth sides: no rectangle.
    Daemon d("group_max_pause_s = 1\n");
    d.source->attach("tablet");
    const auto sides = rectangle_sides(20, 20, 80, 60);
    std::vector<std::uint64_t> ids;
    for (std::size_t i = 0; i < sides.size(); ++i) {
      ids.push_back(d.source->draw("tablet", sides[i], i == 3 ? 1'500'000 : 300'000));
    }
    const auto events = d.collector->shapes(4);
    ASSERT_EQ(events.size(), 4U);
    EXPECT_EQ(ids_of(events[3].shape().replaced_stroke_ids()).size() <= 1, true);
    EXPECT_TRUE(events[3].shape().supersedes_shape_ids().empty());
  }
}

TEST(LiveGrouping, ConfigRpcShowsAndChangesTheGrouping) {
  Daemon d;
  auto config =
      v1::Config::NewStub(grpc::CreateChannel(d.address, grpc::InsecureChannelCredentials()));
  {
    grpc::ClientContext ctx;
    v1::SettingsResponse got;
    ASSERT_TRUE(config->GetSettings(&ctx, v1::GetSettingsRequest{}, &got).ok());
    EXPECT_FALSE(got.grouping().disabled());
    EXPECT_EQ(got.grouping().max_strokes(), 4U);
    EXPECT_EQ(got.grouping().max_pause_s(), 2.0);
    EXPECT_TRUE(got.grouping().tidy_axis());
  }
  auto set = [&](const std::string& key, const v1::GroupingSettings& g, v1::SettingsResponse* out) {
    grpc::ClientContext ctx;
    v1::SetSettingsRequest request;
    request.set_device_key(key);
    *request.mutable_grouping() = g;
    return config->SetSettings(&ctx, request, out);
  };
  v1::SettingsResponse after;
  v1::GroupingSettings bad;
  bad.set_max_strokes(9);
  grpc::Status s = set("", bad, &after);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(s.error_message().find("grouping.max_strokes"), std::string::npos) << s.error_message();
  bad.Clear();
  bad.set_max_pause_s(-0.5);
  s = set("", bad, &after);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(s.error_message().find("grouping.max_pause_s"), std::string::npos) << s.error_message();
  v1::GroupingSettings one;
  one.set_max_strokes(1);
  s = set("056a:0010", one, &after);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(s.error_message().find("device_key"), std::string::npos) << s.error_message();
  ASSERT_TRUE(set("", one, &after).ok());
  EXPECT_EQ(after.grouping().max_strokes(), 1U);
  EXPECT_EQ(after.grouping().max_pause_s(), 2.0); // fields left out are kept

  // From now on every stroke stands alone.
  d.source->attach("tablet");
  d.draw_rectangle("tablet", 20, 20, 80, 60);
  const auto events = d.collector->shapes(4);
  ASSERT_EQ(events.size(), 4U);
  expect_groups_of_at_most(events, 1);
}

// While the fourth side is drawn (the pen held down at its end until one comes), a preview shows
// the rectangle the stroke would complete, naming the three earlier strokes and this one.
TEST(LiveGrouping, PreviewOfTheLastSideShowsTheRectangle) {
  Daemon d("", true);
  d.source->attach("tablet");
  const auto sides = rectangle_sides(20, 20, 80, 60);
  std::vector<std::uint64_t> ids;
  for (std::size_t i = 0; i < 3; ++i) ids.push_back(d.source->draw("tablet", sides[i]));
  ASSERT_EQ(d.collector->shapes(3).size(), 3U);
  const auto give_up = std::chrono::steady_clock::now() + 30s;
  ids.push_back(d.source->draw("tablet", sides[3], 300'000, [&] {
    return d.collector->group_previews() == 0 && std::chrono::steady_clock::now() < give_up;
  }));
  const auto previews = d.collector->group_preview_events();
  ASSERT_FALSE(previews.empty());
  const v1::PreviewCandidates& p = previews.front().preview();
  EXPECT_EQ(p.stroke_id(), ids.back());
  EXPECT_TRUE(is_rectangle(p.group().shape().kind()));
  EXPECT_EQ(ids_of(p.group().replaced_stroke_ids()), ids);
  EXPECT_FALSE(p.group().supersedes_shape_ids().empty());
  EXPECT_LE(p.group().shape().certificate().hausdorff_bound().approx(),
            p.group().shape().certificate().tolerance().approx());
}

} // namespace
