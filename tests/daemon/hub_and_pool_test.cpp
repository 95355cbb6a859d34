#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>

#if defined(__linux__)
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "penshape/daemon/shape_hub.hpp"
#include "penshape/daemon/worker_pool.hpp"

namespace {

using namespace std::chrono_literals;
using penshape::daemon::EventFilter;
using penshape::daemon::ShapeHub;
using penshape::daemon::StopCondition;
using penshape::daemon::WorkerPool;
using penshape::daemon::WorkerPriority;

penshape::v1::LiveEvent stroke_started(std::uint64_t id, const std::string& device = "d") {
  penshape::v1::LiveEvent e;
  e.set_device_id(device);
  e.mutable_stroke_started()->set_stroke_id(id);
  return e;
}

TEST(ShapeHub, ASlowSubscriberLosesItsOldestEventsAndLearnsHowMany) {
  ShapeHub hub(8);
  auto slow = hub.subscribe(EventFilter{}, 3);
  auto fast = hub.subscribe(EventFilter{}, 1000);
  ASSERT_TRUE(slow && fast);
  // The producer never waits: 100 events go out although nobody reads.
  for (std::uint64_t i = 1; i <= 100; ++i) hub.publish(stroke_started(i));
  EXPECT_EQ(hub.published(), 100U);

  auto first = slow->next(0ms);
  ASSERT_TRUE(first.event);
  EXPECT_EQ(first.dropped, 97U); // reported with the first event after the loss
  EXPECT_EQ(first.event->stroke_started().stroke_id(), 98U);
  EXPECT_EQ(first.event->sequence(), 98U);
  EXPECT_TRUE(first.more);
  auto second = slow->next(0ms);
  EXPECT_EQ(second.dropped, 0U);
  EXPECT_TRUE(second.more);
  EXPECT_EQ(second.event->stroke_started().stroke_id(), 99U);
  EXPECT_EQ(slow->dropped_total(), 97U);
  EXPECT_FALSE(slow->next(0ms).more); // the last one

  // The other subscriber got everything, in order.
  for (std::uint64_t i = 1; i <= 100; ++i) {
    auto d = fast->next(0ms);
    ASSERT_TRUE(d.event);
    EXPECT_EQ(d.dropped, 0U);
    EXPECT_EQ(d.event->stroke_started().stroke_id(), i);
  }
  EXPECT_FALSE(fast->next(0ms).event);
}

TEST(ShapeHub, FiltersByKindAndDevice) {
  ShapeHub hub(8);
  EventFilter only_b;
  only_b.device_ids = {"b"};
  auto b = hub.subscribe(only_b, 10);
  EventFilter devices;
  devices.devices = true;
  devices.strokes = false;
  auto watcher = hub.subscribe(devices, 10);
  hub.publish(stroke_started(1, "a"));
  hub.publish(stroke_started(2, "b"));
  penshape::v1::LiveEvent samples;
  samples.set_device_id("b");
  samples.mutable_samples()->add_samples()->set_x(5);
  hub.publish(samples); // samples not requested
  penshape::v1::LiveEvent attached;
  attached.set_device_id("c");
  attached.mutable_device_attached()->mutable_device()->set_id("c");
  hub.publish(attached);

  auto d = b->next(0ms);
  ASSERT_TRUE(d.event);
  EXPECT_EQ(d.event->stroke_started().stroke_id(), 2U);
  EXPECT_FALSE(b->next(0ms).event);
  auto w = watcher->next(0ms);
  ASSERT_TRUE(w.event);
  EXPECT_EQ(w.event->device_attached().device().id(), "c");
  EXPECT_FALSE(watcher->next(0ms).event);
}

TEST(ShapeHub, RefusesBeyondMaxSubscribersAndAfterClose) {
  ShapeHub hub(2);
  auto a = hub.subscribe({}, 1);
  auto b = hub.subscribe({}, 1);
  ShapeHub::Refusal why = ShapeHub::Refusal::kNone;
  EXPECT_FALSE(hub.subscribe({}, 1, &why));
  EXPECT_EQ(why, ShapeHub::Refusal::kFull);
  b.reset(); // unsubscribes
  EXPECT_EQ(hub.subscriber_count(), 1U);
  auto c = hub.subscribe({}, 1, &why);
  EXPECT_TRUE(c);
  hub.close();
  EXPECT_FALSE(hub.subscribe({}, 1, &why));
  EXPECT_EQ(why, ShapeHub::Refusal::kClosed);
}

TEST(ShapeHub, CloseDeliversWhatIsQueuedThenFinishes) {
  ShapeHub hub(2);
  auto s = hub.subscribe({}, 10);
  hub.publish(stroke_started(1));
  hub.publish(stroke_started(2));
  hub.close();
  hub.publish(stroke_started(3)); // after close: discarded
  EXPECT_FALSE(s->finished());
  EXPECT_EQ(s->next(0ms).event->stroke_started().stroke_id(), 1U);
  EXPECT_EQ(s->next(0ms).event->stroke_started().stroke_id(), 2U);
  EXPECT_FALSE(s->next(0ms).event);
  EXPECT_TRUE(s->finished());
}

TEST(ShapeHub, AWaitingSubscriberWakesOnPublish) {
  ShapeHub hub(2);
  auto s = hub.subscribe({}, 10);
  std::thread producer([&] {
    std::this_thread::sleep_for(20ms);
    hub.publish(stroke_started(7));
  });
  auto d = s->next(10s);
  producer.join();
  ASSERT_TRUE(d.event);
  EXPECT_EQ(d.event->stroke_started().stroke_id(), 7U);
}

TEST(WorkerPool, RefusesWhenItsQueueIsFull) {
  WorkerPool pool(1, 2);
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::promise<void> running;
  ASSERT_TRUE(pool.submit([&](const StopCondition&) {
    running.set_value();
    released.wait();
  }));
  running.get_future().wait(); // the only worker is busy; the queue is empty
  std::atomic<int> ran{0};
  EXPECT_TRUE(pool.submit([&](const StopCondition&) { ++ran; }));
  EXPECT_TRUE(pool.submit([&](const StopCondition&) { ++ran; }));
  EXPECT_FALSE(pool.submit([&](const StopCondition&) { ++ran; })); // third queued: refused
  EXPECT_EQ(pool.queued(), 2U);
  release.set_value();
  pool.drain();
  EXPECT_EQ(ran.load(), 2);
  EXPECT_FALSE(pool.accepting());
  EXPECT_FALSE(pool.submit([&](const StopCondition&) { ++ran; }));
}

TEST(WorkerPool, JobsSeeTheirStopCondition) {
  WorkerPool pool(2, 8);
  std::atomic<bool> flag{false};
  std::promise<bool> before;
  std::promise<bool> after;
  std::promise<bool> expired;
  pool.submit(
      [&](const StopCondition& stop) {
        before.set_value(stop.should_stop());
        flag = true;
        after.set_value(stop.should_stop() && stop.cancelled());
      },
      StopCondition(StopCondition::Clock::time_point::max(), [&] { return flag.load(); }));
  pool.submit([&](const StopCondition& stop) { expired.set_value(stop.deadline_passed()); },
              StopCondition(StopCondition::Clock::now() - 1ms, {}));
  EXPECT_FALSE(before.get_future().get());
  EXPECT_TRUE(after.get_future().get());
  EXPECT_TRUE(expired.get_future().get());
}

TEST(WorkerPool, AThrowingJobDoesNotStopTheWorker) {
  WorkerPool pool(1, 4);
  pool.submit([](const StopCondition&) { throw std::runtime_error("boom"); });
  std::promise<int> next;
  pool.submit([&](const StopCondition&) { next.set_value(42); });
  EXPECT_EQ(next.get_future().get(), 42);
}

TEST(ShapeHub, KnowsWhetherAnySubscriberWantsPreviews) {
  ShapeHub hub(4);
  EXPECT_FALSE(hub.wants_previews());
  auto plain = hub.subscribe(EventFilter{}, 4);
  EXPECT_FALSE(hub.wants_previews());
  EventFilter previews;
  previews.previews = true;
  auto a = hub.subscribe(previews, 4);
  auto b = hub.subscribe(previews, 4);
  EXPECT_TRUE(hub.wants_previews());
  a.reset();
  EXPECT_TRUE(hub.wants_previews());
  b.reset();
  EXPECT_FALSE(hub.wants_previews());
}

#if defined(__linux__)
struct ThreadScheduling {
  int nice = 0;
  int policy = 0;
};

// Read on the pool's own thread: what the kernel says, not what the pool meant to set.
ThreadScheduling scheduling_of_a_worker(WorkerPriority priority) {
  const int process_nice = ::getpriority(PRIO_PROCESS, 0);
  WorkerPool pool(1, 1, priority);
  std::promise<ThreadScheduling> seen;
  pool.submit([&](const StopCondition&) {
    const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
    seen.set_value({::getpriority(PRIO_PROCESS, tid) - process_nice, ::sched_getscheduler(0)});
  });
  return seen.get_future().get();
}

TEST(WorkerPool, LanesRunAtTheirDocumentedPriorities) {
  const ThreadScheduling normal = scheduling_of_a_worker(WorkerPriority::kNormal);
  EXPECT_EQ(normal.nice, 0);
  EXPECT_EQ(normal.policy, SCHED_OTHER);
  // Niceness saturates at 19 when the test itself already runs niced.
  const int room = 19 - ::getpriority(PRIO_PROCESS, 0);
  const ThreadScheduling interactive = scheduling_of_a_worker(WorkerPriority::kInteractive);
  EXPECT_EQ(interactive.nice, std::min(penshape::daemon::kInteractiveNice, room));
  EXPECT_EQ(interactive.policy, SCHED_OTHER);
  const ThreadScheduling batch = scheduling_of_a_worker(WorkerPriority::kBatch);
  EXPECT_EQ(batch.nice, std::min(penshape::daemon::kBatchNice, room));
  EXPECT_GE(batch.nice, interactive.nice);
  EXPECT_EQ(scheduling_of_a_worker(WorkerPriority::kIdle).policy, SCHED_IDLE);
}
#endif

} // namespace
