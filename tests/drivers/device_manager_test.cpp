// The device manager without hardware: a fake backend and fake report sources stand in for
// hidraw. Covers attach, samples and strokes, unplug mid-stroke, reconnect, stop, and that a
// replayed recording yields exactly the strokes of the live path.
#include "penshape/drivers/device_manager.hpp"

#include <gtest/gtest.h>

#include <condition_variable>
#include <deque>
#include <mutex>

#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"
#include "shared_data.hpp"

namespace penshape::drivers {
namespace {

using namespace std::chrono_literals;

// A report source the test feeds by hand.
class FakeSource final : public ReportSource {
 public:
  void push(std::vector<std::uint8_t> bytes, std::int64_t t) {
    {
      std::lock_guard lock(mutex_);
      queue_.push_back({t, std::move(bytes)});
      now_ = t;
    }
    cv_.notify_all();
  }
  void vanish() {
    {
      std::lock_guard lock(mutex_);
      gone_ = true;
    }
    cv_.notify_all();
  }
  ReadStatus read(std::vector<std::uint8_t>& bytes, std::int64_t& time_us,
                  std::chrono::milliseconds timeout) override {
    std::unique_lock lock(mutex_);
    cv_.wait_for(lock, timeout, [&] { return !queue_.empty() || gone_ || interrupted_; });
    if (interrupted_) return ReadStatus::kEnd;
    if (!queue_.empty()) {
      bytes = queue_.front().bytes;
      time_us = queue_.front().time_us;
      queue_.pop_front();
      return ReadStatus::kReport;
    }
    return gone_ ? ReadStatus::kGone : ReadStatus::kTimeout;
  }
  std::int64_t now_us() const override {
    std::lock_guard lock(mutex_);
    return now_;
  }
  void interrupt() override {
    {
      std::lock_guard lock(mutex_);
      interrupted_ = true;
    }
    cv_.notify_all();
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<HidEvent> queue_;
  std::int64_t now_ = 0;
  bool gone_ = false;
  bool interrupted_ = false;
};

// Devices appear and disappear when the test says so; each open() yields a new FakeSource (or
// a source made by `make_source`).
class FakeBackend final : public DeviceBackend {
 public:
  std::function<std::unique_ptr<ReportSource>()> make_source;

  void plug(DeviceCandidate c) {
    {
      std::lock_guard lock(mutex_);
      present_.push_back(std::move(c));
    }
    wake();
  }
  void unplug(const std::string& key) {
    std::lock_guard lock(mutex_);
    std::erase_if(present_, [&](const DeviceCandidate& c) { return c.key == key; });
  }
  FakeSource* last_source() {
    std::lock_guard lock(mutex_);
    return last_;
  }
  int opens() {
    std::lock_guard lock(mutex_);
    return opens_;
  }

  std::vector<DeviceCandidate> scan() override {
    std::lock_guard lock(mutex_);
    return present_;
  }
  VendorStrings read_vendor_strings(const DeviceCandidate&,
                                    std::span<const std::uint8_t>) override {
    return {};
  }
  std::unique_ptr<ReportSource> open(const DeviceCandidate&,
                                     const std::vector<InitStep>&) override {
    std::lock_guard lock(mutex_);
    ++opens_;
    if (make_source) return make_source();
    auto s = std::make_unique<FakeSource>();
    last_ = s.get();
    return s;
  }
  void wait_for_change(std::chrono::milliseconds timeout) override {
    std::unique_lock lock(mutex_);
    cv_.wait_for(lock, timeout, [&] { return woken_; });
    woken_ = false;
  }
  void wake() override {
    {
      std::lock_guard lock(mutex_);
      woken_ = true;
    }
    cv_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  std::vector<DeviceCandidate> present_;
  FakeSource* last_ = nullptr;
  int opens_ = 0;
  bool woken_ = false;
};

// What the callbacks saw, in order.
struct Journal {
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<std::string> events; // "attach", "stroke", "detach:<reason>"
  std::vector<AttachedDevice> attached;
  std::vector<Stroke> strokes;
  std::vector<PenSample> samples;

  DeviceCallbacks callbacks() {
    return {
        .on_attach =
            [this](const AttachedDevice& d) {
              std::lock_guard lock(mutex);
              attached.push_back(d);
              events.push_back("attach");
              cv.notify_all();
            },
        .on_detach =
            [this](DeviceId, DetachReason why, const PipelineCounters&) {
              std::lock_guard lock(mutex);
              events.push_back(why == DetachReason::kGone    ? "detach:gone"
                               : why == DetachReason::kEnded ? "detach:ended"
                                                             : "detach:stopped");
              cv.notify_all();
            },
        .on_sample =
            [this](DeviceId, const PenSample& s) {
              std::lock_guard lock(mutex);
              samples.push_back(s);
              cv.notify_all();
            },
        .on_stroke =
            [this](DeviceId, Stroke&& s) {
              std::lock_guard lock(mutex);
              strokes.push_back(std::move(s));
              events.push_back("stroke");
              cv.notify_all();
            },
    };
  }
  bool wait_for(const std::function<bool()>& pred) {
    std::unique_lock lock(mutex);
    return cv.wait_for(lock, 10s, pred);
  }
  std::size_t count(const std::string& e) {
    return static_cast<std::size_t>(std::count(events.begin(), events.end(), e));
  }
};

DeviceManagerOptions rescan_every(std::chrono::milliseconds interval) {
  DeviceManagerOptions o;
  o.rescan_interval = interval;
  o.reattach_backoff = std::chrono::milliseconds(100);
  return o;
}

Recording penpartner() { return read_hid_recorder(read_file(testing::penpartner_capture())); }

DeviceCandidate penpartner_candidate(const std::string& key) {
  const Recording r = penpartner();
  DeviceCandidate c;
  c.key = key;
  c.identity = r.identity;
  c.descriptor = r.descriptor;
  return c;
}

// A Graphire-protocol pen report (the PenPartner's): in range, tip, x, y, pressure.
std::vector<std::uint8_t> pen(bool tip, int x, int y, int pressure) {
  return {0x02,
          static_cast<std::uint8_t>(0x80 | (tip ? 1 : 0)),
          static_cast<std::uint8_t>(x & 0xFF),
          static_cast<std::uint8_t>(x >> 8),
          static_cast<std::uint8_t>(y & 0xFF),
          static_cast<std::uint8_t>(y >> 8),
          static_cast<std::uint8_t>(pressure & 0xFF),
          static_cast<std::uint8_t>((pressure >> 8) & 3)};
}

TEST(DeviceManager, UnplugMidStrokeEndsTheStrokeAndLosesNoFinishedOne) {
  auto backend = std::make_unique<FakeBackend>();
  FakeBackend* fake = backend.get();
  Journal j;
  DeviceManager m(std::move(backend), j.callbacks(), rescan_every(50ms));
  fake->plug(penpartner_candidate("/dev/hidraw-fake0"));
  m.start();
  ASSERT_TRUE(j.wait_for([&] { return j.attached.size() == 1 && fake->last_source(); }));
  EXPECT_EQ(j.attached[0].tablet.x_max, 3250);
  FakeSource* src = fake->last_source();
  // One complete stroke, then a second one cut by the unplug.
  std::int64_t t = 0;
  for (int i = 0; i < 5; ++i) src->push(pen(true, 100 + i, 200, 50), t += 8000);
  src->push(pen(false, 105, 200, 0), t += 8000);
  src->push(pen(false, 106, 200, 0), t += 30000); // past the debounce window
  for (int i = 0; i < 4; ++i) src->push(pen(true, 300 + i, 400, 80), t += 8000);
  fake->unplug("/dev/hidraw-fake0");
  src->vanish();
  ASSERT_TRUE(j.wait_for([&] { return j.count("detach:gone") == 1; }));
  std::lock_guard lock(j.mutex);
  ASSERT_EQ(j.strokes.size(), 2U);
  EXPECT_EQ(j.strokes[0].samples.size(), 6U); // 5 down + the tip-up
  EXPECT_EQ(j.strokes[1].samples.size(), 5U); // 4 down + the synthetic end
  const PenSample& end = j.strokes[1].samples.back();
  EXPECT_FALSE(end.tip);
  EXPECT_FALSE(end.in_range);
  EXPECT_EQ(end.x, 303);
  EXPECT_EQ(end.time_us, t);
  EXPECT_NE(j.strokes[0].id, j.strokes[1].id);
  // The cut stroke is delivered before the detach event.
  ASSERT_GE(j.events.size(), 4U);
  EXPECT_EQ(j.events.back(), "detach:gone");
  EXPECT_EQ(j.events[j.events.size() - 2], "stroke");
}

TEST(DeviceManager, ReconnectsWhenTheDeviceComesBack) {
  auto backend = std::make_unique<FakeBackend>();
  FakeBackend* fake = backend.get();
  Journal j;
  DeviceManager m(std::move(backend), j.callbacks(), rescan_every(50ms));
  fake->plug(penpartner_candidate("/dev/hidraw-fake1"));
  m.start();
  ASSERT_TRUE(j.wait_for([&] { return j.attached.size() == 1 && fake->last_source(); }));
  // Suspend/resume: the read fails while the node stays listed; the manager reopens it.
  fake->last_source()->vanish();
  const auto vanished = std::chrono::steady_clock::now();
  ASSERT_TRUE(j.wait_for([&] { return j.attached.size() == 2; }));
  // Not reopened before the back-off (a node failing at once must not spin the rescan).
  EXPECT_GE(std::chrono::steady_clock::now() - vanished, 100ms);
  EXPECT_NE(j.attached[0].id, j.attached[1].id);
  EXPECT_EQ(fake->opens(), 2);
  EXPECT_EQ(m.devices().size(), 1U);
  m.stop();
  EXPECT_EQ(j.count("detach:gone"), 1U);
  EXPECT_EQ(j.count("detach:stopped"), 1U);
}

TEST(DeviceManager, StopEndsAnOpenStroke) {
  auto backend = std::make_unique<FakeBackend>();
  FakeBackend* fake = backend.get();
  Journal j;
  DeviceManager m(std::move(backend), j.callbacks(), rescan_every(50ms));
  fake->plug(penpartner_candidate("/dev/hidraw-fake2"));
  m.start();
  ASSERT_TRUE(j.wait_for([&] { return fake->last_source() != nullptr; }));
  for (int i = 0; i < 3; ++i)
    fake->last_source()->push(pen(true, 10, 10 + i, 9), std::int64_t{1000} * i);
  ASSERT_TRUE(j.wait_for([&] { return j.samples.size() == 3; }));
  m.stop();
  ASSERT_EQ(j.strokes.size(), 1U);
  EXPECT_EQ(j.strokes[0].samples.size(), 4U);
  EXPECT_EQ(j.events.back(), "detach:stopped");
}

TEST(DeviceManager, DevicesWithoutAPenAreIgnored) {
  auto backend = std::make_unique<FakeBackend>();
  FakeBackend* fake = backend.get();
  Journal j;
  DeviceManager m(std::move(backend), j.callbacks(), rescan_every(20ms));
  // A keyboard-only descriptor on an unknown VID/PID.
  DeviceCandidate kbd;
  kbd.key = "/dev/hidraw-kbd";
  kbd.identity.vendor_id = 0x1234;
  kbd.identity.product_id = 0x5678;
  kbd.descriptor = {0x05, 0x01, 0x09, 0x06, 0xA1, 0x01, 0x05, 0x07, 0x19, 0xE0, 0x29, 0xE7,
                    0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x08, 0x81, 0x02, 0xC0};
  fake->plug(kbd);
  m.start();
  std::this_thread::sleep_for(100ms);
  EXPECT_EQ(fake->opens(), 0);
  EXPECT_TRUE(m.devices().empty());
}

// The live path (backend -> reader thread -> pipeline) and replay() give identical strokes.
void expect_same_strokes(const std::vector<Stroke>& a, const std::vector<Stroke>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].samples, b[i].samples) << "stroke " << i;
    EXPECT_EQ(a[i].tablet, b[i].tablet);
  }
}

TEST(DeviceManager, ReplayYieldsTheStrokesOfTheLivePath) {
  const Recording rec = penpartner();
  const ReplayResult offline = replay(rec, ReplaySpeed::kAsFastAsPossible);
  ASSERT_GE(offline.strokes.size(), 3U);

  auto backend = std::make_unique<FakeBackend>();
  FakeBackend* fake = backend.get();
  // The recording is served once: the device stays plugged, so a rescan after the replay ended
  // may open it again (a quiet source then), which must not replay the strokes a second time.
  fake->make_source = [&rec, served = false]() mutable -> std::unique_ptr<ReportSource> {
    if (served) return std::make_unique<FakeSource>();
    served = true;
    return std::make_unique<RecordingSource>(rec.events, ReplaySpeed::kAsFastAsPossible);
  };
  Journal j;
  DeviceManager m(std::move(backend), j.callbacks(), rescan_every(10s));
  DeviceCandidate c;
  c.key = "/dev/hidraw-replayed";
  c.identity = rec.identity;
  c.descriptor = rec.descriptor;
  fake->plug(c);
  m.start();
  ASSERT_TRUE(j.wait_for([&] { return j.count("detach:ended") == 1; }));
  fake->unplug("/dev/hidraw-replayed");
  m.stop();
  std::lock_guard lock(j.mutex);
  expect_same_strokes(j.strokes, offline.strokes);
  EXPECT_EQ(j.samples, offline.samples);
}

TEST(DeviceManager, AttachReplayAtOriginalSpeedMatchesFastReplay) {
  // A short slice of the PenPartner capture (about 1.3 s) at its original pace.
  Recording rec = penpartner();
  rec.events.resize(160);
  const ReplayResult fast = replay(rec, ReplaySpeed::kAsFastAsPossible);
  Journal j;
  DeviceManager m(nullptr, j.callbacks());
  const auto start = std::chrono::steady_clock::now();
  m.attach_replay(rec, ReplaySpeed::kOriginal);
  ASSERT_TRUE(j.wait_for([&] { return j.count("detach:ended") == 1; }));
  const auto took = std::chrono::steady_clock::now() - start;
  const auto span_us = rec.events.back().time_us - rec.events.front().time_us;
  EXPECT_GE(std::chrono::duration_cast<std::chrono::microseconds>(took).count(), span_us);
  std::lock_guard lock(j.mutex);
  expect_same_strokes(j.strokes, fast.strokes);
}

// The raw-report callback gets every report as read — those that decode to a sample, a report ID
// the pen layout does not know, an out-of-range frame — each before the sample it decodes to; the
// attach event carries what a capture's header needs (the kernel's name and phys win).
TEST(DeviceManager, EveryReportReachesTheReportCallbackBeforeItsSample) {
  auto backend = std::make_unique<FakeBackend>();
  FakeBackend* fake = backend.get();
  Journal j;
  std::mutex order_mutex;
  std::vector<std::string> order;
  std::vector<HidEvent> reports;
  DeviceCallbacks callbacks = j.callbacks();
  callbacks.on_sample = [&, inner = callbacks.on_sample](DeviceId id, const PenSample& s) {
    {
      std::lock_guard lock(order_mutex);
      order.push_back("sample " + std::to_string(s.time_us));
    }
    inner(id, s);
  };
  DeviceManager m(std::move(backend), std::move(callbacks), rescan_every(50ms),
                  [&](DeviceId, std::span<const std::uint8_t> bytes, std::int64_t t) {
                    {
                      std::lock_guard lock(order_mutex);
                      order.push_back("report " + std::to_string(t));
                      reports.push_back({t, std::vector<std::uint8_t>(bytes.begin(), bytes.end())});
                    }
                    { std::lock_guard wake(j.mutex); } // the waiter is checking or waiting
                    j.cv.notify_all();
                  });
  DeviceCandidate c = penpartner_candidate("/dev/hidraw-fake-raw");
  c.hid_name = "WACOM Fake HID Name";
  c.phys = "usb-fake-1/input0";
  fake->plug(c);
  m.start();
  ASSERT_TRUE(j.wait_for([&] { return j.attached.size() == 1 && fake->last_source(); }));
  {
    std::lock_guard lock(j.mutex);
    const Recording& header = j.attached[0].header;
    EXPECT_EQ(header.identity.name, "WACOM Fake HID Name");
    EXPECT_EQ(header.phys, "usb-fake-1/input0");
    EXPECT_TRUE(header.has_identity);
    EXPECT_EQ(header.identity.vendor_id, 0x056a);
    EXPECT_EQ(header.identity.product_id, 0x0061);
    EXPECT_EQ(header.descriptor, penpartner().descriptor);
    EXPECT_TRUE(header.events.empty());
  }
  const std::vector<HidEvent> sent{
      {1000, pen(true, 100, 200, 50)},
      {2000, {0x63, 0, 0, 0, 0, 0, 0, 0}}, // another report ID: no sample
      {3000, pen(true, 0x7fff, 200, 50)},  // beyond x_max (3250): dropped as corrupt
      {4000, pen(false, 101, 200, 0)},
      {5000, {0x02}}, // too short: junk
  };
  FakeSource* src = fake->last_source();
  for (const HidEvent& e : sent) src->push(e.bytes, e.time_us);
  ASSERT_TRUE(j.wait_for([&] {
    std::lock_guard lock(order_mutex);
    return reports.size() == sent.size();
  }));
  m.stop();
  std::lock_guard lock(order_mutex);
  EXPECT_EQ(reports, sent);
  EXPECT_EQ(order,
            (std::vector<std::string>{"report 1000", "sample 1000", "report 2000", "report 3000",
                                      "report 4000", "sample 4000", "report 5000"}));
}

// Replays hand the recording's own header and every event to the same callback.
TEST(DeviceManager, ReplaysPassEveryRecordedReportOn) {
  Recording rec = penpartner();
  rec.events.resize(200);
  Journal j;
  std::mutex mutex;
  std::vector<HidEvent> reports;
  DeviceManager m(nullptr, j.callbacks(), {},
                  [&](DeviceId, std::span<const std::uint8_t> bytes, std::int64_t t) {
                    std::lock_guard lock(mutex);
                    reports.push_back({t, std::vector<std::uint8_t>(bytes.begin(), bytes.end())});
                  });
  m.attach_replay(rec, ReplaySpeed::kAsFastAsPossible);
  ASSERT_TRUE(j.wait_for([&] { return j.count("detach:ended") == 1; }));
  std::lock_guard lock(mutex);
  EXPECT_EQ(reports, rec.events);
  std::lock_guard journal_lock(j.mutex);
  ASSERT_EQ(j.attached.size(), 1U);
  Recording header = rec;
  header.events.clear();
  EXPECT_EQ(j.attached[0].header, header);
}

} // namespace
} // namespace penshape::drivers
