// BuildOnce: a value built exactly once by whichever thread asks first; the owner waits only for
// a build already under way, and every caller sees the build's error.
#include "penshape/daemon/build_once.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <thread>

namespace {

using namespace std::chrono_literals;
using penshape::daemon::BuildOnce;

TEST(BuildOnce, TheOwnerBuildsWhenNoHelperStarted) {
  std::atomic<int> builds{0};
  BuildOnce<int> value([&] {
    ++builds;
    return 42;
  });
  EXPECT_EQ(value.get(), 42);
  EXPECT_EQ(&value.get(), &value.get());
  value.build_if_not_started(); // a helper that comes late builds nothing
  EXPECT_EQ(builds.load(), 1);
}

TEST(BuildOnce, AHelperThatFinishedIsNotRepeated) {
  std::atomic<int> builds{0};
  BuildOnce<int> value([&] { return ++builds * 10; });
  std::thread([&] { value.build_if_not_started(); }).join();
  EXPECT_EQ(builds.load(), 1);
  EXPECT_EQ(value.get(), 10);
  EXPECT_EQ(builds.load(), 1);
}

TEST(BuildOnce, TheOwnerWaitsForAHelperAlreadyBuilding) {
  std::promise<void> started;
  std::atomic<int> builds{0};
  std::atomic<bool> finished{false};
  BuildOnce<int> value([&] {
    ++builds;
    started.set_value();
    std::this_thread::sleep_for(50ms);
    finished = true;
    return 7;
  });
  std::thread helper([&] { value.build_if_not_started(); });
  started.get_future().wait();
  EXPECT_EQ(value.get(), 7);
  EXPECT_TRUE(finished.load()); // get() returned only once the helper's build was done
  helper.join();
  EXPECT_EQ(builds.load(), 1);
}

TEST(BuildOnce, RacingCallersBuildExactlyOnce) {
  for (int round = 0; round < 200; ++round) {
    std::atomic<int> builds{0};
    BuildOnce<int> value([&] {
      ++builds;
      return round;
    });
    std::thread helper([&] { value.build_if_not_started(); });
    std::thread other([&] { EXPECT_EQ(value.get(), round); });
    EXPECT_EQ(value.get(), round);
    helper.join();
    other.join();
    ASSERT_EQ(builds.load(), 1) << "round " << round;
  }
}

TEST(BuildOnce, EveryCallerSeesTheBuildsError) {
  BuildOnce<int> value([]() -> int { throw std::invalid_argument("no ink"); });
  EXPECT_NO_THROW(value.build_if_not_started()); // the helper never throws
  EXPECT_THROW(value.get(), std::invalid_argument);
  EXPECT_THROW(value.get(), std::invalid_argument);
}

} // namespace
