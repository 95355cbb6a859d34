// The queue adapter: a replay through the manager arrives as attach, samples and strokes in
// time order, then detach; a full queue drops the oldest samples only.
#include "penshape/drivers/device_event_queue.hpp"

#include <gtest/gtest.h>

#include "shared_data.hpp"

namespace penshape::drivers {
namespace {

using namespace std::chrono_literals;

TEST(DeviceEventQueue, ReplayArrivesInOrder) {
  const Recording rec = read_hid_recorder(read_file(testing::penpartner_capture()));
  const ReplayResult expected = replay(rec, ReplaySpeed::kAsFastAsPossible);
  DeviceEventQueue queue;
  DeviceManager manager(nullptr, queue.callbacks());
  const DeviceId id = manager.attach_replay(rec, ReplaySpeed::kAsFastAsPossible);
  std::vector<DeviceEvent> events;
  while (auto e = queue.pop(10s)) {
    events.push_back(std::move(*e));
    if (events.back().kind == DeviceEvent::Kind::kDetach) break;
  }
  ASSERT_GE(events.size(), 2U);
  EXPECT_EQ(events.front().kind, DeviceEvent::Kind::kAttach);
  EXPECT_EQ(events.front().attached.tablet.x_max, 3250);
  EXPECT_EQ(events.back().reason, DetachReason::kEnded);
  EXPECT_EQ(events.back().counters.pen_samples, expected.samples.size());
  std::vector<PenSample> samples;
  std::size_t strokes = 0;
  for (const auto& e : events) {
    EXPECT_EQ(e.device, id);
    if (e.kind == DeviceEvent::Kind::kSample) samples.push_back(e.sample);
    if (e.kind == DeviceEvent::Kind::kStroke) {
      EXPECT_EQ(e.stroke.samples, expected.strokes.at(strokes).samples);
      // A stroke comes after its last sample.
      EXPECT_GE(samples.back().time_us, e.stroke.samples.back().time_us);
      ++strokes;
    }
  }
  EXPECT_EQ(samples, expected.samples);
  EXPECT_EQ(strokes, expected.strokes.size());
  EXPECT_EQ(queue.dropped_samples(), 0U);
}

TEST(DeviceEventQueue, FullQueueDropsOldestSamplesOnly) {
  DeviceEventQueue queue(2);
  const DeviceCallbacks cb = queue.callbacks();
  cb.on_attach(AttachedDevice{7, "k", {}, Protocol::kHid});
  for (int i = 0; i < 5; ++i) {
    PenSample s;
    s.x = i;
    cb.on_sample(7, s);
  }
  Stroke st;
  st.id = 1;
  cb.on_stroke(7, std::move(st));
  EXPECT_EQ(queue.dropped_samples(), 3U);
  ASSERT_EQ(queue.size(), 4U);
  EXPECT_EQ(queue.pop(0ms)->kind, DeviceEvent::Kind::kAttach);
  EXPECT_EQ(queue.pop(0ms)->sample.x, 3);
  EXPECT_EQ(queue.pop(0ms)->sample.x, 4);
  EXPECT_EQ(queue.pop(0ms)->kind, DeviceEvent::Kind::kStroke);
  EXPECT_FALSE(queue.pop(1ms));
}

} // namespace
} // namespace penshape::drivers
