// The parameter-search subcommands and `deconstruct --simplify`, run as a user would.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "generated_files.hpp"
#include "run_command.hpp"
#include "test_data.hpp"

namespace {

using penshape::test::run_command;
using penshape::testing::coast_file;

std::string cli(const std::string& args) { return std::string(PENSHAPE_CLI) + " " + args; }

double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return -1e300;
  return std::stod(json.substr(at + key.size() + 3));
}

TEST(SearchCli, ToleranceIntervalAndSolution) {
  const auto r =
      run_command(cli("search-tolerance " + coast_file() + " --radius 10 --precision 0.05 --json"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const double lo = json_number(r.out, "eps_low");
  const double hi = json_number(r.out, "eps_high");
  EXPECT_GE(lo, 0);
  EXPECT_LE(hi - lo, 0.05 + 1e-12);
  EXPECT_LE(json_number(r.out, "eps_solution"), lo + 2 * 0.05);
  for (const char* key : {"\"answer\":\"YES\"", "\"solution\":[{\"outer\":[[", "\"raw_vertices\":",
                          "\"solution_vertices\":", "\"decider_calls\":", "\"seconds\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
  EXPECT_LE(json_number(r.out, "solution_vertices"), json_number(r.out, "raw_vertices"));
}

TEST(SearchCli, RadiusBounds) {
  const auto r = run_command(cli("search-radius " + coast_file() + " --tolerance 5 --json"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const double lo = json_number(r.out, "r_low");
  const double hi = json_number(r.out, "r_high");
  EXPECT_GE(lo, 5); // r <= ε always has a solution
  EXPECT_GE(hi, lo);
  EXPECT_NE(r.out.find("\"converged\":"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"undecided_calls\":"), std::string::npos) << r.out;
}

TEST(SearchCli, SuggestRadiusReportsProgressAndSuggestions) {
  const auto r = run_command(cli("suggest-radius " + coast_file() + " --samples 5 --json"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("suggest-radius: 5/5 radii"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"suggestions\":[{\"radius\":"), std::string::npos) << r.out;
  const auto quiet = run_command(cli("suggest-radius " + coast_file() + " --samples 3 --quiet"));
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.out.find("radii"), std::string::npos) << quiet.out;
}

void expect_simplified_by_default(const std::string& file, const std::string& params) {
  const auto simplified = run_command(cli("deconstruct " + file + params + " --json"));
  const auto raw = run_command(cli("deconstruct " + file + params + " --json --no-simplify"));
  ASSERT_EQ(simplified.exit_code, 0) << simplified.out;
  ASSERT_EQ(raw.exit_code, 0) << raw.out;
  EXPECT_NE(simplified.out.find("\"simplified\":true"), std::string::npos);
  EXPECT_NE(raw.out.find("\"simplified\":false"), std::string::npos);
  EXPECT_LT(json_number(simplified.out, "solution_vertices"),
            json_number(raw.out, "solution_vertices") / 2);
}

TEST(SearchCli, DeconstructSimplifiesByDefault) {
  PENSHAPE_SHARED_OR_SKIP(file, "polygons/kazakhstan_paper1881.txt");
  expect_simplified_by_default(file.string(), " --radius 0.0237 --tolerance 0.0118");
}

TEST(SearchCli, DeconstructSimplifiesAGeneratedCoastlineByDefault) {
  // 1,881 vertices about 2,000 units across: r = w / 40.
  expect_simplified_by_default(penshape::testing::write_generated(
                                   "country1881.txt", penshape::gen::country(4, 1881, 1000.0).text),
                               " --radius 50 --tolerance 25");
}

// tests/data/adversarial/slit.txt: the fast engine stays UNDECIDED far above ε̂ there (a slit
// narrower than δ), breaking the search's assumption. The CLI must still exit 0 with a
// converged interval (settled by the reference engine) that overlaps the reference engine's
// own search's interval: both hold ε̂, so they must meet.
TEST(SearchCli, SlitIsSettledByTheReferenceFallback) {
  const std::string file = (penshape::test::bundled_data_dir() / "adversarial/slit.txt").string();
  const auto fast =
      run_command(cli("search-tolerance " + file + " --radius 1 --precision 1/256 --json"));
  ASSERT_EQ(fast.exit_code, 0) << fast.out;
  const auto ref = run_command(
      cli("search-tolerance " + file + " --radius 1 --precision 1/256 --engine reference --json"));
  ASSERT_EQ(ref.exit_code, 0) << ref.out;
  EXPECT_NE(fast.out.find("\"converged\":true"), std::string::npos) << fast.out;
  EXPECT_NE(fast.out.find("\"answer\":\"YES\""), std::string::npos) << fast.out;
  EXPECT_GT(json_number(fast.out, "fallback_calls"), 0) << fast.out;
  EXPECT_EQ(json_number(ref.out, "fallback_calls"), 0) << ref.out;
  const double lo = json_number(fast.out, "eps_low");
  const double hi = json_number(fast.out, "eps_high");
  EXPECT_LE(hi - lo, 1.0 / 256 + 1e-12);
  EXPECT_LE(lo, json_number(ref.out, "eps_high"));
  EXPECT_GE(hi, json_number(ref.out, "eps_low"));
}

TEST(SearchCli, BadInputExitsTwo) {
  EXPECT_EQ(run_command(cli("search-tolerance /nonexistent --radius 1")).exit_code, 2);
  EXPECT_EQ(run_command(cli("search-tolerance " + coast_file() + " --radius nan")).exit_code, 2);
  EXPECT_EQ(run_command(cli("search-radius " + coast_file())).exit_code,
            2); // --tolerance is required
  EXPECT_EQ(run_command(cli("suggest-radius " + coast_file() + " --samples 2")).exit_code, 2);
  EXPECT_EQ(run_command(cli("search-tolerance " + coast_file() + " --radius -3")).exit_code, 2);
}

} // namespace

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(SvgCli, DeconstructAndRecognizeDrawPictures) {
  const std::string svg = std::string(PENSHAPE_BINARY_DIR) + "/svg_cli_test.svg";
  std::remove(svg.c_str());
  const auto d =
      run_command(cli("deconstruct " + coast_file() + " --radius 10 --tolerance 5 --svg " + svg));
  ASSERT_EQ(d.exit_code, 0) << d.out;
  const std::string picture = slurp(svg);
  EXPECT_NE(picture.find("<svg"), std::string::npos);
  EXPECT_NE(picture.find(" 0 0 1 "), std::string::npos) << "offset(P, r) is drawn with true arcs";
  EXPECT_NE(picture.find("</svg>"), std::string::npos);
  EXPECT_EQ(run_command(cli("deconstruct " + coast_file() +
                            " --radius 10 --tolerance 5 --svg /nonexistent/dir/x.svg"))
                .exit_code,
            2);

  const std::string dir = std::string(PENSHAPE_BINARY_DIR) + "/svg_cli_test_dir";
  const auto r = run_command(
      cli("recognize --svg-dir " + dir + " " + penshape::testing::stroke_file("rectangle", 1)));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string stroke = slurp(dir + "/generated_rectangle01_1-2.svg");
  EXPECT_NE(stroke.find("<svg"), std::string::npos);
  EXPECT_NE(stroke.find("rectangle"), std::string::npos);
}

} // namespace
