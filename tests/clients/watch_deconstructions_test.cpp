// `penshape watch --deconstructions` against a daemon with the real deconstruction engine: after
// each stroke's shape comes its offset deconstruction (the ink here is the stroke's box widened by
// the pen radius, so P is the certified inset rectangle).
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "child_process.hpp"
#include "dollar_stroke.hpp"
#include "penshape/daemon/geometry_backend.hpp"
#include "test_daemon.hpp"

namespace penshape::testing {
namespace {

const std::string kCli = PENSHAPE_CLI;

std::vector<PenSample> rectangle_samples() {
  return samples_from_points(read_dollar_gesture(dollar_rectangle_path()), 40.0, 2000, 1000);
}

TEST(WatchDeconstructions, JsonCarriesTheCertifiedOutlineAfterTheShape) {
  TestDaemon daemon("watch-deconstruct-json", true, daemon::make_core_geometry_backend());
  daemon.source->attach("pen-a");
  ChildProcess watch(
      {kCli, "watch", "--json", "--deconstructions", "--count", "4", "--address", daemon.address});
  ASSERT_TRUE(watch.wait_for_output("subscribed to " + daemon.address)) << watch.output();
  daemon.source->draw("pen-a", rectangle_samples());
  ASSERT_EQ(watch.wait(), 0) << watch.output();
  std::vector<std::string> events;
  std::istringstream in(watch.output());
  for (std::string line; std::getline(in, line);) {
    if (line.rfind('{', 0) == 0) events.push_back(line);
  }
  ASSERT_EQ(events.size(), 4U) << watch.output();
  EXPECT_NE(events[2].find("\"type\":\"shape\""), std::string::npos) << events[2];
  const std::string& d = events[3];
  EXPECT_NE(d.find("\"type\":\"deconstructed\",\"stroke_id\":1,\"not_deconstructed\":\"\","
                   "\"answer\":\"YES\""),
            std::string::npos)
      << d;
  EXPECT_NE(d.find("\"solution_vertices\":4"), std::string::npos) << d; // a rectangle's inset
  const std::regex number(R"re("(tolerance|hausdorff_bound)":([0-9.e+-]+))re");
  std::map<std::string, double> values;
  for (auto it = std::sregex_iterator(d.begin(), d.end(), number); it != std::sregex_iterator();
       ++it) {
    values[(*it)[1]] = std::stod((*it)[2]);
  }
  ASSERT_EQ(values.size(), 2U) << d;
  EXPECT_LE(values["hausdorff_bound"], values["tolerance"]);
}

TEST(WatchDeconstructions, ReadableLineNamesTheAnswerAndTheOutline) {
  TestDaemon daemon("watch-deconstruct-text", true, daemon::make_core_geometry_backend());
  daemon.source->attach("pen-a");
  ChildProcess watch(
      {kCli, "watch", "--deconstructions", "--count", "4", "--address", daemon.address});
  ASSERT_TRUE(watch.wait_for_output("subscribed to")) << watch.output();
  daemon.source->draw("pen-a", rectangle_samples());
  ASSERT_EQ(watch.wait(), 0) << watch.output();
  EXPECT_NE(watch.output().find("[pen-a] stroke 1 deconstructed: YES, P has 4 vertices"),
            std::string::npos)
      << watch.output();
}

TEST(WatchDeconstructions, WithoutAnEngineTheEventSaysWhy) {
  TestDaemon daemon("watch-deconstruct-none");
  daemon.source->attach("pen-a");
  ChildProcess watch(
      {kCli, "watch", "--deconstructions", "--count", "4", "--address", daemon.address});
  ASSERT_TRUE(watch.wait_for_output("subscribed to")) << watch.output();
  daemon.source->draw("pen-a", rectangle_samples());
  ASSERT_EQ(watch.wait(), 0) << watch.output();
  EXPECT_NE(watch.output().find(
                "stroke 1 deconstructed: not done (this build has no deconstruction engine)"),
            std::string::npos)
      << watch.output();
}

} // namespace
} // namespace penshape::testing
