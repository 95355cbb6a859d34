// clients/python/penshape_watch.py against a daemon the test serves: it subscribes and prints the
// shape of a hand-drawn rectangle (the $1 data set) that the test double recognizer snaps to a
// square.
#include <gtest/gtest.h>
#include <unistd.h>

#include <regex>

#include "child_process.hpp"
#include "dollar_stroke.hpp"
#include "test_daemon.hpp"

namespace penshape::testing {
namespace {

const std::string kPython = "/usr/bin/python3";
const std::string kScript = std::string(PENSHAPE_SOURCE_DIR) + "/clients/python/penshape_watch.py";
const std::map<std::string, std::string> kEnv = {{"PYTHONPATH", PENSHAPE_PYTHON_STUBS}};

class PythonExample : public ::testing::Test {
 protected:
  void SetUp() override {
    if (::access(kPython.c_str(), X_OK) != 0) GTEST_SKIP() << kPython << " is not installed";
    const auto [code, out] = run_program({kPython, "-c", "import grpc, google.protobuf"});
    if (code != 0) {
      GTEST_SKIP() << "python3-grpcio is not installed (scripts/setup.sh installs it): " << out;
    }
  }
};

TEST_F(PythonExample, PrintsTheShapeOfAStroke) {
  TestDaemon daemon("python");
  daemon.source->attach("pen-a");
  ChildProcess client({kPython, kScript, "--address", daemon.address, "--count", "1"}, kEnv);
  ASSERT_TRUE(client.wait_for_output("subscribed to " + daemon.address)) << client.output();
  const auto samples =
      samples_from_points(read_dollar_gesture(dollar_rectangle_path()), 40.0, 2000, 1000);
  const Stroke stroke = daemon.source->draw("pen-a", samples);
  ASSERT_EQ(client.wait(), 0) << client.output();
  // The square the test double answers, from the stroke's box in mm.
  const BoxMm b = tip_box_mm(stroke);
  const double h = ((b.x1 - b.x0) + (b.y1 - b.y0)) / 4;
  char first[64];
  std::snprintf(first, sizeof first, "(%.2f, %.2f)", (b.x0 + b.x1) / 2 - h, (b.y0 + b.y1) / 2 - h);
  const std::string out = client.output();
  EXPECT_NE(out.find("stroke 1 on pen-a: square " + std::string(first)), std::string::npos) << out;
  EXPECT_NE(out.find("within 0.25 mm of the ink (tolerance 0.5 mm)"), std::string::npos) << out;
}

TEST_F(PythonExample, JsonAndErrors) {
  {
    TestDaemon daemon("python-json");
    daemon.source->attach("pen-a");
    ChildProcess client({kPython, kScript, "--json", "--address", daemon.address, "--count", "1"},
                        kEnv);
    ASSERT_TRUE(client.wait_for_output("subscribed to")) << client.output();
    daemon.source->draw("pen-a", samples_from_points(read_dollar_gesture(dollar_rectangle_path()),
                                                     40.0, 2000, 1000));
    ASSERT_EQ(client.wait(), 0) << client.output();
    EXPECT_NE(client.output().find(R"({"device_id": "pen-a", "stroke_id": 1, "kind": "square")"),
              std::string::npos)
        << client.output();
  }
  {
    const auto [code, out] =
        run_program({kPython, kScript, "--address", unique_test_address("py-none")}, kEnv);
    EXPECT_EQ(code, 1) << out;
    EXPECT_NE(out.find("penshaped is not running at"), std::string::npos) << out;
  }
  {
    const auto [code, out] = run_program({kPython, kScript, "--count", "x"}, kEnv);
    EXPECT_EQ(code, 2) << out;
  }
}

} // namespace
} // namespace penshape::testing
