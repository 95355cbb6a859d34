// RecordingSource in virtual time: a gap between reports becomes the live path's timeouts, and a
// gap of any length (a recording may hold years) costs few of them.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"
#include "shared_data.hpp"

namespace penshape::drivers {
namespace {

constexpr std::chrono::milliseconds kPoll{10};
constexpr std::int64_t kPollUs = 10'000;

// The virtual times of the timeouts read before the second event, due `gap_us` after the first.
std::vector<std::int64_t> timeouts_in_gap(std::int64_t gap_us) {
  RecordingSource source({{.time_us = 0, .bytes = {1}}, {.time_us = gap_us, .bytes = {2}}},
                         ReplaySpeed::kAsFastAsPossible);
  std::vector<std::uint8_t> bytes;
  std::int64_t t = 0;
  EXPECT_EQ(source.read(bytes, t, kPoll), ReadStatus::kReport);
  std::vector<std::int64_t> ticks;
  for (;;) {
    const ReadStatus st = source.read(bytes, t, kPoll);
    if (st != ReadStatus::kTimeout) {
      EXPECT_EQ(st, ReadStatus::kReport);
      EXPECT_EQ(t, gap_us);
      return ticks;
    }
    ticks.push_back(source.now_us());
    if (ticks.size() > 1'000'000) return ticks; // would never end
  }
}

// The live path's last timeout: polls every kPollUs until the report is due.
std::int64_t last_live_timeout(std::int64_t gap_us) {
  std::int64_t now = 0;
  while (gap_us - now > kPollUs) now += kPollUs;
  return now;
}

TEST(RecordingSource, AGapOfYearsCostsFewTimeouts) {
  const std::int64_t gap = 1'000'000'000'000LL * 1'000'000; // the largest timestamp a file may hold
  const auto ticks = timeouts_in_gap(gap);
  ASSERT_FALSE(ticks.empty());
  EXPECT_LT(ticks.size(), 200U);
  EXPECT_EQ(ticks.back(), kPollUs * ((gap - 1) / kPollUs)); // the last whole poll before it
}

TEST(RecordingSource, GapTimeoutsAreLiveTimeoutsEndingOnTheLastOne) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> gap_us(0, 60 * kPollUs);
  for (int i = 0; i < 2000; ++i) {
    const std::int64_t gap = gap_us(rng);
    const auto ticks = timeouts_in_gap(gap);
    std::int64_t previous = 0;
    for (const std::int64_t tick : ticks) {
      EXPECT_EQ(tick % kPollUs, 0) << "gap " << gap; // a whole number of polls, as live
      EXPECT_GT(tick, previous) << "gap " << gap;
      previous = tick;
    }
    if (gap > kPollUs) {
      ASSERT_FALSE(ticks.empty()) << "gap " << gap;
      EXPECT_EQ(ticks.back(), last_live_timeout(gap)) << "gap " << gap;
      EXPECT_EQ(last_live_timeout(gap), kPollUs * ((gap - 1) / kPollUs)) << "gap " << gap;
    } else {
      EXPECT_TRUE(ticks.empty()) << "gap " << gap;
    }
  }
}

TEST(RecordingSource, AZeroPollDeliversEveryReport) {
  RecordingSource source({{.time_us = 0, .bytes = {1}}, {.time_us = 5'000, .bytes = {2}}},
                         ReplaySpeed::kAsFastAsPossible);
  std::vector<std::uint8_t> bytes;
  std::int64_t t = 0;
  EXPECT_EQ(source.read(bytes, t, std::chrono::milliseconds(0)), ReadStatus::kReport);
  EXPECT_EQ(source.read(bytes, t, std::chrono::milliseconds(0)), ReadStatus::kReport);
  EXPECT_EQ(t, 5'000);
  EXPECT_EQ(source.read(bytes, t, std::chrono::milliseconds(0)), ReadStatus::kEnd);
}

// The generated recording with a pause put after its middle event: a pause of ten seconds and one
// of thirty thousand years cut the same strokes.
TEST(RecordingSource, ALongPauseCutsTheStrokesAShortOneDoes) {
  const Recording original = read_hid_recorder(read_file(testing::penpartner_capture()));
  ASSERT_GT(original.events.size(), 10U);
  auto paused = [&](std::int64_t pause_us) {
    Recording r = original;
    for (std::size_t i = r.events.size() / 2; i < r.events.size(); ++i) {
      r.events[i].time_us += pause_us;
    }
    return replay(r, ReplaySpeed::kAsFastAsPossible);
  };
  const std::int64_t short_pause = 10'000'000;
  const std::int64_t long_pause = 1'000'000'000'000'000LL;
  const auto a = paused(short_pause);
  const auto b = paused(long_pause);
  ASSERT_EQ(a.strokes.size(), b.strokes.size());
  ASSERT_GT(a.strokes.size(), 1U);
  for (std::size_t i = 0; i < a.strokes.size(); ++i) {
    ASSERT_EQ(a.strokes[i].samples.size(), b.strokes[i].samples.size()) << "stroke " << i;
    for (std::size_t k = 0; k < a.strokes[i].samples.size(); ++k) {
      PenSample sa = a.strokes[i].samples[k];
      PenSample sb = b.strokes[i].samples[k];
      if (sb.time_us >= long_pause) sb.time_us -= long_pause - short_pause;
      EXPECT_EQ(sa, sb) << "stroke " << i << " sample " << k;
    }
  }
}

} // namespace
} // namespace penshape::drivers
