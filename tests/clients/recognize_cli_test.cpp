// `penshape recognize` run as a user would: $1 logs, JSON lines, --json, --labels, bad input.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "generated_files.hpp"
#include "test_data.hpp"

namespace {

struct Result {
  int exit_code = -1;
  std::string out;
};

Result run(const std::string& args) {
  const std::string cmd = std::string(PENSHAPE_CLI) + " recognize " + args + " 2>&1";
  Result r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) r.out += buf.data();
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// A hand-drawn triangle made by the stroke generator, as a $1 gesture log.
std::filesystem::path triangle_file() { return penshape::testing::stroke_file("triangle", 6); }

std::string quoted(const std::filesystem::path& p) {
  std::string out(1, '\'');
  out.append(p.string());
  out.push_back('\'');
  return out;
}

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  auto path = std::filesystem::temp_directory_path() /
              ("penshape_recognize_cli_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path;
}

TEST(RecognizeCli, DollarLogToJson) {
  const auto file = triangle_file();
  const Result r = run("--json " + quoted(file));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* key : {"\"file\":", "\"class\":\"triangle\"",
                          "\"confidence\":", "\"params\":{\"vertices\":", "\"alternatives\":[",
                          "\"corners\":4", "\"certified\":true", "\"seconds\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
}

TEST(RecognizeCli, JsonLinesWithLabelsPrintsAConfusionTable) {
  const auto file =
      write_temp("ok.jsonl",
                 "{\"points\":[[0,0,0],[100,0,0.1],[200,0,0.2]],\"label\":\"segment\"}\n"
                 "\n"
                 "{\"name\":\"box\",\"points\":[[0,0],[100,0],[100,100],[0,100],[0,0]],\"label\":"
                 "\"square\"}\n");
  const Result r = run("--labels " + quoted(file));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("-> segment"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("-> square"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("overall: 2 / 2 correct"), std::string::npos) << r.out;
  std::filesystem::remove(file);
}

TEST(RecognizeCli, BadInputNamesFileAndLine) {
  const auto bad_json =
      write_temp("bad.jsonl", "{\"points\":[[0,0],[1,1]]}\n{\"points\":[[0,0],[1,]]}\n");
  Result r = run(quoted(bad_json));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find(bad_json.string() + ":2:"), std::string::npos) << r.out;

  const auto single = write_temp("single.jsonl", "{\"points\":[[5,5,0]]}\n");
  r = run(quoted(single)); // a dot is a stroke (issue 23), never an error: alone it is writing
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("-> freeform (writing)"), std::string::npos) << r.out;
  r = run("--snap-writing " + quoted(single)); // recognized, it is a dot
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("-> dot"), std::string::npos) << r.out;

  const auto nan = write_temp("nan.xml",
                              "<Gesture Name=\"circle01\">\n<Point X=\"1\" Y=\"2\" T=\"0\" />\n"
                              "<Point X=\"nan\" Y=\"2\" T=\"1\" />\n</Gesture>\n");
  r = run(quoted(nan));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find(nan.string() + ":3:"), std::string::npos) << r.out;

  const auto truncated = write_temp("cut.xml", "<Gesture Name=\"x\">\n<Point X=\"1\" Y=\"2\" ");
  r = run(quoted(truncated));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unterminated"), std::string::npos) << r.out;

  EXPECT_EQ(run("/nonexistent/stroke.jsonl").exit_code, 2);
  EXPECT_EQ(run("").exit_code, 2);
  EXPECT_EQ(run("--pen-radius -1 " + quoted(single)).exit_code, 2);
  for (const auto& f : {bad_json, single, nan, truncated}) std::filesystem::remove(f);
}

// A circle of radius 50 as JSON lines; `pressure(t)` in [0, 1] per point (or none).
std::string circle_jsonl(double (*pressure)(double)) {
  std::ostringstream line;
  line << "{\"points\":[";
  for (int k = 0; k <= 200; ++k) {
    const double t = 2 * 3.141592653589793 * k / 200;
    line << (k > 0 ? "," : "") << "[" << 100 + 50 * std::cos(t) << "," << 100 + 50 * std::sin(t)
         << "," << k * 0.01;
    if (pressure) line << "," << pressure(t);
    line << "]";
  }
  line << "],\"label\":\"circle\"}\n";
  return line.str();
}

TEST(RecognizeCli, InkCertificateAndPressure) {
  const auto dollar = triangle_file();
  Result r = run("--ink --json " + quoted(dollar));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\"class\":\"triangle\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"certificate_method\":\"ink\""), std::string::npos) << r.out;
  r = run("--json " + quoted(dollar));
  EXPECT_NE(r.out.find("\"certificate_method\":\"path\""), std::string::npos) << r.out;
  EXPECT_EQ(run("--ink --pressure " + quoted(dollar)).exit_code, 2) << "$1 XML has no pressure";
  EXPECT_EQ(run("--pressure " + quoted(dollar)).exit_code, 2) << "--pressure needs --ink";

  // Even pressure: a circle, certified on the ink.
  const auto even = write_temp("even.jsonl", circle_jsonl([](double) { return 0.8; }));
  r = run("--ink --pressure --pen-radius 10 --tolerance 3 --json " + quoted(even));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\"class\":\"circle\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"certificate_method\":\"ink\""), std::string::npos) << r.out;
  // Pressed hard on a quarter of it: the path is the same circle, the ink bulges by far more
  // than the tolerance, so it must not snap on the ink (it does on the paths).
  const auto bulge = write_temp(
      "bulge.jsonl", circle_jsonl([](double t) { return t > 1.0 && t < 2.5 ? 1.0 : 0.1; }));
  r = run("--ink --pressure --pen-radius 10 --tolerance 3 --json " + quoted(bulge));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\"name\":\"\",\"class\":\"freeform\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"certificate_method\":\"ink\""), std::string::npos) << r.out;
  r = run("--pen-radius 10 --tolerance 3 --json " + quoted(bulge));
  EXPECT_NE(r.out.find("\"name\":\"\",\"class\":\"circle\""), std::string::npos) << r.out;

  const auto mixed = write_temp("mixed.jsonl", "{\"points\":[[0,0,0,0.5],[10,0,1]]}\n");
  r = run("--ink " + quoted(mixed));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("every point or for none"), std::string::npos) << r.out;
  const auto out_of_range = write_temp("range.jsonl", "{\"points\":[[0,0,0,1.5],[10,0,1,1]]}\n");
  EXPECT_EQ(run(quoted(out_of_range)).exit_code, 2);
  for (const auto& f : {even, bulge, mixed, out_of_range}) std::filesystem::remove(f);
}

} // namespace

namespace {

// A straight stroke as a JSON-lines row from (x0, y0) to (x1, y1), times from t0.
std::string side(double x0, double y0, double x1, double y1, double t0) {
  std::ostringstream row;
  row << "{\"points\":[";
  for (int k = 0; k <= 20; ++k) {
    row << (k ? "," : "") << "[" << x0 + (x1 - x0) * k / 20.0 << "," << y0 + (y1 - y0) * k / 20.0
        << "," << t0 + 0.01 * k << "]";
  }
  row << "],\"label\":\"rectangle\"}\n";
  return row.str();
}

TEST(RecognizeCli, JsonLinesAreGroupedInDrawingOrder) {
  const auto file =
      write_temp("sides.jsonl", side(0, 0, 200, 0, 0) + side(200, 0, 200, 120, 0.5) +
                                    side(200, 120, 0, 120, 1.0) + side(0, 120, 0, 0, 1.5));
  Result r = run("--json --labels " + quoted(file));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\"lines\":[1,2,3,4]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"class\":\"rectangle\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"tidy\":["), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"correct\":1"), std::string::npos) << r.out;
  r = run("--json --no-group " + quoted(file));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("\"lines\":[1,2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"lines\":[4]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"class\":\"segment\""), std::string::npos) << r.out;

  const auto svg = std::filesystem::temp_directory_path() /
                   ("penshape_recognize_cli_svg_" + std::to_string(::getpid()));
  r = run("--svg-dir " + quoted(svg) + " " + quoted(file));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(std::filesystem::exists(svg / (file.stem().string() + "-1.svg"))) << r.out;
  std::filesystem::remove_all(svg);
  std::filesystem::remove(file);
}

TEST(RecognizeCli, JsonLinesDecodeEscapesAndRefuseBadTimes) {
  const auto escaped =
      write_temp("escaped.jsonl",
                 "{\"name\":\"caf\\u00e9\\r\\b\",\"points\":[[0,0,0],[100,0,0.1],[200,0,0.2]]}\n");
  Result r = run("--json " + quoted(escaped));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("caf\xC3\xA9\\r\\u0008"), std::string::npos) << r.out;

  struct Bad {
    const char* name;
    const char* text;
    const char* says;
  };
  for (const Bad& b :
       {Bad{"same_t.jsonl", "{\"points\":[[0,0,0],[1,1,0.1],[2,2,0.1]]}\n", "same time"},
        Bad{"back_t.jsonl", "{\"points\":[[0,0,0.2],[1,1,0.1]]}\n", "backwards"},
        Bad{"none.jsonl", "{\"points\":[]}\n", "no points"},
        Bad{"nan.jsonl", "{\"points\":[[0,0,0],[NaN,1,0.1]]}\n", "not valid JSON"},
        Bad{"huge.jsonl", "{\"points\":[[0,0,0],[1e999,1,0.1]]}\n", "JSON"},
        Bad{"text.jsonl", "{\"points\":[[0,0,0],[\"1\",1,0.1]]}\n", "number"},
        Bad{"some_t.jsonl", "{\"points\":[[0,0,0],[1,1]]}\n", "every point"},
        Bad{"order.jsonl", "{\"points\":[[0,0,1],[1,1,2]]}\n\n{\"points\":[[0,0,0],[1,1,0.5]]}\n",
            "before the previous stroke"}}) {
    const auto f = write_temp(b.name, b.text);
    r = run(quoted(f));
    EXPECT_EQ(r.exit_code, 2) << b.name << ": " << r.out;
    const std::string line = std::string(b.name) == "order.jsonl" ? ":3:" : ":1:";
    EXPECT_NE(r.out.find(f.string() + line), std::string::npos) << b.name << ": " << r.out;
    EXPECT_NE(r.out.find(b.says), std::string::npos) << b.name << ": " << r.out;
    std::filesystem::remove(f);
  }
  std::filesystem::remove(escaped);
}

} // namespace
