// `penshape deconstruct` run as a user would, on generated polygons of known answer (the shared
// demo polygons' answers are checked in tests/core).
#include <gtest/gtest.h>

#include "generated_files.hpp"
#include "run_command.hpp"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

using Result = penshape::test::CommandResult;

Result run(const std::string& args) {
  return penshape::test::run_command(std::string(PENSHAPE_CLI) + " deconstruct " + args);
}

using penshape::testing::rounded_hexagon_file;

TEST(DeconstructCli, RoundedHexagonIsYesWithJsonKeys) {
  const Result r =
      run(rounded_hexagon_file() + " --radius 1 --tolerance 0.1 --engine reference --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.rfind("{\"answer\":\"YES\",\"engine\":\"reference\",\"seconds\":", 0), 0U)
      << r.out;
  for (const char* key : {"\"solution\":[{\"outer\":[[", "\"holes\":[]",
                          "\"solution_vertices\":", "\"hausdorff_bound\":0.1", "\"disk_vertices\":",
                          "\"params\":{\"radius\":1,\"tolerance\":0.1,\"precision\":0.0125}"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
}

TEST(DeconstructCli, SquareIsNo) {
  const Result r = run(penshape::testing::square_file() +
                       " --radius 1 --tolerance 0.1 --engine reference --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.rfind("{\"answer\":\"NO\"", 0), 0U) << r.out;
  EXPECT_NE(r.out.find("\"solution\":[]"), std::string::npos) << r.out;
}

TEST(DeconstructCli, WktInput) {
  const std::string path = std::string(PENSHAPE_BINARY_DIR) + "/deconstruct_cli_square.wkt";
  std::ofstream(path) << "POLYGON ((0 0, 5 0, 5 5, 0 5, 0 0))\n";
  const Result r = run(path + " --radius 1 --tolerance 0.1 --precision 0.01 --engine reference");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("answer: NO"), std::string::npos) << r.out;
}

TEST(DeconstructCli, BadInputExitsTwo) {
  EXPECT_EQ(run("/nonexistent/file.txt --radius 1 --tolerance 0.1").exit_code, 2);
  EXPECT_EQ(run(rounded_hexagon_file() + " --tolerance 0.1").exit_code, 2);
  const Result nan = run(rounded_hexagon_file() + " --radius nan --tolerance 0.1");
  EXPECT_EQ(nan.exit_code, 2);
  EXPECT_NE(nan.out.find("--radius"), std::string::npos) << nan.out;
  const Result coarse = run(rounded_hexagon_file() + " --radius 1 --tolerance 0.1 --precision 0.5");
  EXPECT_EQ(coarse.exit_code, 2);
  EXPECT_NE(coarse.out.find("precision must be smaller than the tolerance"), std::string::npos)
      << coarse.out;
  EXPECT_EQ(run(rounded_hexagon_file() + " --radius 1 --tolerance 0.1 --engine quick").exit_code,
            2);
}

TEST(DeconstructCli, MalformedFileNamesTheLine) {
  const std::string path = std::string(PENSHAPE_BINARY_DIR) + "/deconstruct_cli_bad.txt";
  std::ofstream(path) << "# header\n0 0\n1 0\n1 x\n";
  const Result r = run(path + " --radius 1 --tolerance 0.1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("line 4"), std::string::npos) << r.out;
}

// The file is read in one piece of its size when it is a regular file; a pipe has no size and
// is read to its end, and a directory is refused without reading gigabytes of zeros.
TEST(DeconstructCli, PipeIsReadLikeTheFile) {
  const std::string args = " --radius 1 --tolerance 0.1 --engine reference";
  const Result from_file = run(rounded_hexagon_file() + args);
  const Result from_pipe = penshape::test::run_command(
      "cat " + rounded_hexagon_file() + " | " + PENSHAPE_CLI + " deconstruct /dev/stdin" + args);
  ASSERT_EQ(from_file.exit_code, 0) << from_file.out;
  ASSERT_EQ(from_pipe.exit_code, 0) << from_pipe.out;
  const auto without_seconds = [](const std::string& out) {
    const std::size_t at = out.find("seconds:");
    return out.substr(0, at) + out.substr(out.find('\n', at));
  };
  EXPECT_EQ(without_seconds(from_pipe.out), without_seconds(from_file.out));
  const Result directory = run(std::string(PENSHAPE_BINARY_DIR) + args);
  EXPECT_EQ(directory.exit_code, 2) << directory.out;
}

TEST(DeconstructCli, SelfIntersectingFileIsRejected) {
  const std::string path = std::string(PENSHAPE_BINARY_DIR) + "/deconstruct_cli_bowtie.txt";
  std::ofstream(path) << "0 0\n4 4\n4 0\n0 6\n";
  const Result r = run(path + " --radius 1 --tolerance 0.1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("self-intersecting"), std::string::npos) << r.out;
}

// The region is validated once, by the CLI, before the parameters (issue 26): a bad file with a
// bad precision names the file's fault, with the file's name; coordinates past ±1e12 either way
// are refused by name.
TEST(DeconstructCli, TheFileIsCheckedBeforeTheParameters) {
  const std::string path = std::string(PENSHAPE_BINARY_DIR) + "/deconstruct_cli_bowtie2.txt";
  std::ofstream(path) << "0 0\n4 4\n4 0\n0 6\n";
  const Result r = run(path + " --radius 1 --tolerance 0.1 --precision 0.5");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find(path + ": polygon 0, outer ring is self-intersecting"), std::string::npos)
      << r.out;
  for (const char* far : {"2000000000000.5", "-2000000000000.5"}) {
    const std::string far_path = std::string(PENSHAPE_BINARY_DIR) + "/deconstruct_cli_far.txt";
    std::ofstream(far_path) << "0 0\n1 0\n" << far << " 1\n";
    const Result f = run(far_path + " --radius 1 --tolerance 0.1");
    EXPECT_EQ(f.exit_code, 2);
    EXPECT_NE(f.out.find("vertex 2: a coordinate beyond the limit of ±1e12"), std::string::npos)
        << f.out;
  }
}

} // namespace

namespace {

TEST(DeconstructCli, ArcsOfTheSolutionOffset) {
  const Result r =
      run(rounded_hexagon_file() + " --radius 1 --tolerance 0.1 --engine reference --json --arcs");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\"offset\":[{\"outer\":[{\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("{\"arc\":{\"center\":["), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"radius\":1,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("{\"segment\":[["), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"offset_max_error\":"), std::string::npos) << r.out;
}

} // namespace
