// `penshape verify` run as a user would: deconstruct answers written by `penshape deconstruct
// --json` verify, corrupted ones fail with exit code 1, bad input exits 2.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "run_command.hpp"

namespace {

using Result = penshape::test::CommandResult;

std::string cli() { return PENSHAPE_CLI; }

std::string write(const std::string& name, const std::string& text) {
  const std::string path = std::string(PENSHAPE_BINARY_DIR) + "/verify_cli_" + name;
  std::ofstream(path) << text;
  return path;
}

std::string square() { return write("square.txt", "0 0\n10 0\n10 10\n0 10\n"); }

std::string spike() {
  return write("spike.txt", "0 0\n20 0\n20 9.9\n30 9.9\n30 10.1\n20 10.1\n20 20\n0 20\n");
}

// Runs deconstruct --json and writes its output next to the tests.
std::string answer(const std::string& polygon, const std::string& args, const std::string& name) {
  const Result r =
      penshape::test::run_command(cli() + " deconstruct " + polygon + " " + args + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  return write(name, r.out);
}

Result verify(const std::string& polygon, const std::string& answer_file,
              const std::string& extra = "") {
  return penshape::test::run_command(cli() + " verify " + polygon + " " + answer_file + extra);
}

TEST(VerifyCli, YesAnswersVerify) {
  for (const char* engine : {"fast", "reference"}) {
    const std::string a =
        answer(square(), std::string("--radius 2 --tolerance 0.5 --engine ") + engine, "yes.json");
    const Result r = verify(square(), a);
    EXPECT_EQ(r.exit_code, 0) << engine << ": " << r.out;
    EXPECT_EQ(r.out, "verified\n");
  }
}

TEST(VerifyCli, NoAnswerWitnessVerifies) {
  const std::string a = answer(spike(), "--radius 1 --tolerance 0.25", "no.json");
  const Result r = verify(spike(), a, " --json");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\"answer\":\"NO\",\"status\":\"verified\",\"verified\":true"),
            std::string::npos)
      << r.out;
}

TEST(VerifyCli, ShrunkToleranceIsRefuted) {
  // P is the square shrunk by about 1.5; Q's corner is 1.5·√2 - 2 > 0.1 outside offset(P, 2).
  const Result d = penshape::test::run_command(cli() + " deconstruct " + square() +
                                               " --radius 2 --tolerance 0.5 --json");
  ASSERT_EQ(d.exit_code, 0) << d.out;
  std::string text = d.out;
  const std::string from = "\"tolerance\":\"1/2\",\"precision\":\"1/16\"";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, from.size(), "\"tolerance\":\"1/10\",\"precision\":\"1/100\"");
  const Result r = verify(square(), write("shrunk.json", text));
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("YES refuted: "), std::string::npos) << r.out;
}

TEST(VerifyCli, JsonLinesReportEachAnswer) {
  const Result yes = penshape::test::run_command(cli() + " deconstruct " + square() +
                                                 " --radius 2 --tolerance 0.5 --json");
  const Result no = penshape::test::run_command(cli() + " deconstruct " + square() +
                                                " --radius 8 --tolerance 0.5 --json");
  const Result r = verify(square(), write("lines.json", yes.out + no.out));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("answer 1: verified\nanswer 2: verified\n"), std::string::npos) << r.out;
}

TEST(VerifyCli, BadInputExitsTwo) {
  const std::string a = answer(square(), "--radius 2 --tolerance 0.5", "good.json");
  EXPECT_EQ(verify("/nonexistent/q.txt", a).exit_code, 2);
  EXPECT_EQ(verify(square(), "/nonexistent/a.json").exit_code, 2);
  const Result broken =
      verify(square(), write("broken.json", "{\"answer\": \"YES\",\n  \"params\": ["));
  EXPECT_EQ(broken.exit_code, 2);
  EXPECT_NE(broken.out.find("JSON line 2"), std::string::npos) << broken.out;
  const Result other = verify(square(), write("other.json", "{\"shape\": \"circle\"}"));
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.out.find("not a deconstruct --json answer"), std::string::npos) << other.out;
  const Result missing =
      verify(square(), write("missing.json", "{\"answer\":\"YES\",\"params\":{\"radius\":2}}"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.out.find("params.tolerance"), std::string::npos) << missing.out;
  EXPECT_EQ(penshape::test::run_command(cli() + " verify " + square()).exit_code, 2);
}

} // namespace
