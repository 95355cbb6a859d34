// `penshape verify` run as a user would: deconstruct answers written by `penshape deconstruct
// --json` verify, corrupted ones fail with exit code 1, bad input exits 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "generated_corpus.hpp"
#include "generated_files.hpp"
#include "run_command.hpp"
#include "test_data.hpp"

namespace {

// Strokes along polylines, one JSON line each, 30 samples a side 10 ms apart, the times running
// on from stroke to stroke.
std::string strokes_json(const std::vector<std::vector<std::array<double, 2>>>& strokes) {
  std::string text;
  double t = 0;
  for (const auto& corners : strokes) {
    text += "{\"points\": [";
    for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
      for (int k = i == 0 ? 0 : 1; k <= 30; ++k, t += 0.01) {
        const double f = k / 30.0;
        char buf[96];
        std::snprintf(buf, sizeof buf, "%s[%.6f, %.6f, %.3f]", text.back() == '[' ? "" : ", ",
                      corners[i][0] + f * (corners[i + 1][0] - corners[i][0]),
                      corners[i][1] + f * (corners[i + 1][1] - corners[i][1]), t);
        text += buf;
      }
    }
    text += "]}\n";
    t += 0.3;
  }
  return text;
}

// One stroke drawn through the corners in order (a JSON line).
std::string polyline_stroke_json(const std::vector<std::array<double, 2>>& corners) {
  return strokes_json({corners});
}

using Result = penshape::test::CommandResult;

std::string cli() { return PENSHAPE_CLI; }

// Each test in its own file names: ctest runs the tests of this file in parallel processes.
std::string write(const std::string& name, const std::string& text) {
  std::string path = std::string(PENSHAPE_BINARY_DIR) + "/verify_cli_" +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
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

// ---- Recognition answers ----

// `recognize FILE --json` written next to the tests, and `verify FILE` on it.
Result recognize_and_verify(const std::string& strokes, std::string* answer_out = nullptr) {
  const Result rec = penshape::test::run_command(cli() + " recognize '" + strokes + "' --json");
  EXPECT_EQ(rec.exit_code, 0) << strokes << ": " << rec.out;
  const std::string a = write("recognized.json", rec.out);
  if (answer_out) *answer_out = rec.out;
  return penshape::test::run_command(cli() + " verify '" + strokes + "' " + a);
}

// Every stroke file under `dir`, every `stride`th in sorted order.
std::vector<std::string> stroke_files(const std::filesystem::path& dir, std::size_t stride) {
  std::vector<std::string> all;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (e.path().extension() == ".xml") all.push_back(e.path().string());
  }
  std::sort(all.begin(), all.end());
  std::vector<std::string> out;
  for (std::size_t i = 0; i < all.size(); i += stride) out.push_back(all[i]);
  return out;
}

TEST(VerifyCli, RecognitionsOfGeneratedStrokesVerify) {
  const auto files = stroke_files(penshape::gen::generated_dollar_dir(), 5);
  ASSERT_GT(files.size(), 150U); // every fifth file (all 765 take too long)
  for (const std::string& f : files) {
    const Result r = recognize_and_verify(f);
    EXPECT_EQ(r.exit_code, 0) << f << ": " << r.out;
  }
}

TEST(VerifyCli, RecognitionsOfSharedStrokesVerify) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/dollar1");
  for (const std::string& f : stroke_files(dir, 40)) {
    const Result r = recognize_and_verify(f);
    EXPECT_EQ(r.exit_code, 0) << f << ": " << r.out;
  }
}

// Replaces the first `from` in `text` by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from << " in " << text;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

double number_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos) << key << " in " << text;
  return at == std::string::npos ? 0.0 : std::stod(text.substr(at + key.size()));
}

// A circle's recognition, corrupted: its centre moved by 2 eps, eps shrunk below the stroke's
// own wander, the class swapped for a chord, and bad input; only the truth verifies.
void expect_corruptions_fail(const std::string& f) {
  std::string answer;
  ASSERT_EQ(recognize_and_verify(f, &answer).exit_code, 0);
  ASSERT_NE(answer.find("\"class\":\"circle\""), std::string::npos) << answer;
  const auto run = [&](const std::string& text) {
    return penshape::test::run_command(cli() + " verify '" + f + "' " +
                                       write("corrupt.json", text));
  };
  const double eps = number_after(answer, "\"epsilon\":");
  const double radius = number_after(answer, "\"radius_x\":");
  const auto c = answer.find("\"center\":[") + 10;
  const auto comma = answer.find(',', c);
  const double cx = std::stod(answer.substr(c, comma - c));
  const double cy = std::stod(answer.substr(comma + 1));
  // The centre moved by 2 eps to the right.
  const Result moved =
      run(answer.substr(0, c) + std::to_string(cx + 2 * eps) + answer.substr(comma));
  EXPECT_EQ(moved.exit_code, 1) << moved.out;
  EXPECT_NE(moved.out.find("circle "), std::string::npos) << moved.out;
  // eps shrunk to a tenth of a pixel (a hand's stroke wanders more than that from any circle).
  const auto e = answer.find("\"epsilon\":") + 10;
  const auto e_end = answer.find(',', e);
  const Result shrunk = run(answer.substr(0, e) + "0.1" + answer.substr(e_end));
  EXPECT_EQ(shrunk.exit_code, 1) << shrunk.out;
  // The class swapped: a segment, a horizontal chord through the centre.
  const std::string chord = "[[" + std::to_string(cx - radius) + "," + std::to_string(cy) + "],[" +
                            std::to_string(cx + radius) + "," + std::to_string(cy) + "]]";
  const Result swapped =
      run(replaced(replaced(answer, "\"class\":\"circle\"", "\"class\":\"segment\""),
                   "\"params\":{", "\"params\":{\"vertices\":" + chord + ","));
  EXPECT_EQ(swapped.exit_code, 1) << swapped.out;
  EXPECT_NE(swapped.out.find("segment refuted"), std::string::npos) << swapped.out;
  // The certificate's bound lowered to a quarter (issue #22: verify checked only eps): the claim
  // H <= bound is what is verified, so this fails; a bound raised above eps is refuted.
  const auto b = answer.find("\"bound\":", answer.find("\"certificate\":{")) + 8;
  const auto b_end = answer.find(',', b);
  const double bound = std::stod(answer.substr(b, b_end - b));
  const Result lowered =
      run(answer.substr(0, b) + std::to_string(bound / 4) + answer.substr(b_end));
  EXPECT_EQ(lowered.exit_code, 1) << lowered.out;
  const Result raised = run(answer.substr(0, b) + "1000" + answer.substr(b_end));
  EXPECT_EQ(raised.exit_code, 1) << raised.out;
  EXPECT_NE(raised.out.find("exceeds eps"), std::string::npos) << raised.out;
  // Bad input: no certificate, an unknown class, a line with no stroke.
  EXPECT_EQ(run(replaced(answer, "\"certificate\":{", "\"certificat\":{")).exit_code, 2);
  EXPECT_EQ(run(replaced(answer, "\"class\":\"circle\"", "\"class\":\"blob\"")).exit_code, 2);
  EXPECT_EQ(run(replaced(answer, "\"lines\":[", "\"lines\":[99,")).exit_code, 2);
}

TEST(VerifyCli, CorruptedRecognitionsFail) {
  PENSHAPE_SHARED_OR_SKIP(f, "strokes/dollar1/s02/medium/circle03.xml");
  expect_corruptions_fail(f.string());
}

TEST(VerifyCli, CorruptedRecognitionsOfAGeneratedCircleFail) {
  expect_corruptions_fail(penshape::testing::stroke_file("circle", 4));
}

// A rectangle drawn as two L's (JSON lines): one answer for both strokes ("lines": [1, 2]); it
// verifies on their union, and a corner moved by 2 eps does not.
TEST(VerifyCli, GroupAnswerIsCheckedOnTheUnion) {
  std::string text;
  double t = 0;
  const auto point = [&](double x, double y) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "[%.6f, %.6f, %.3f]", x, y, t);
    text += buf;
  };
  const auto stroke = [&](std::initializer_list<std::pair<double, double>> corners) {
    std::vector<std::pair<double, double>> c(corners);
    text += "{\"points\": [";
    for (std::size_t i = 0; i + 1 < c.size(); ++i) {
      for (int k = 0; k < 30; ++k, t += 0.01) {
        const double f = k / 30.0;
        point(c[i].first + f * (c[i + 1].first - c[i].first) + 0.3 * std::sin(t * 50),
              c[i].second + f * (c[i + 1].second - c[i].second));
        text += ", ";
      }
    }
    point(c.back().first, c.back().second);
    text += "]}\n";
    t += 0.3;
  };
  stroke({{0, 0}, {100, 0}, {100, 60}});
  stroke({{100, 60}, {0, 60}, {0, 0}});
  const std::string strokes = write("two_ls.jsonl", text);
  std::string answer;
  const Result ok = recognize_and_verify(strokes, &answer);
  ASSERT_NE(answer.find("\"lines\":[1,2]"), std::string::npos) << answer;
  ASSERT_NE(answer.find("\"class\":\"rectangle\""), std::string::npos) << answer;
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_EQ(ok.out, "verified\n");
  // The first corner moved 30 to the right (eps is about 15).
  const auto v = answer.find("\"vertices\":[[") + 13;
  const auto comma = answer.find(',', v);
  const double x = std::stod(answer.substr(v, comma - v));
  const std::string moved = answer.substr(0, v) + std::to_string(x + 30.0) + answer.substr(comma);
  const Result bad = penshape::test::run_command(cli() + " verify " + strokes + " " +
                                                 write("two_ls_moved.json", moved));
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
}

// A "hockey stick" arrow in one stroke (JSON lines), drawn with a known pen (--pen-radius 2, so
// epsilon is 10): the answer's shaft has a bend ("shaft_bends"), it verifies, and the same answer
// with the bend moved by 2 epsilon does not.
TEST(VerifyCli, BentArrowAnswerVerifiesAndAMovedBendDoesNot) {
  const double pi = std::acos(-1.0);
  const double tail[2] = {0, 0}, bend[2] = {90, 0}, tip[2] = {200, -60};
  const double back = std::atan2(bend[1] - tip[1], bend[0] - tip[0]);
  const double barb1[2] = {tip[0] + 45 * std::cos(back + pi / 6),
                           tip[1] + 45 * std::sin(back + pi / 6)};
  const double barb2[2] = {tip[0] + 45 * std::cos(back - pi / 6),
                           tip[1] + 45 * std::sin(back - pi / 6)};
  const std::string text = polyline_stroke_json({{tail[0], tail[1]},
                                                 {bend[0], bend[1]},
                                                 {tip[0], tip[1]},
                                                 {barb1[0], barb1[1]},
                                                 {tip[0], tip[1]},
                                                 {barb2[0], barb2[1]}});
  const std::string strokes = write("hockey_stick.jsonl", text);
  const Result rec =
      penshape::test::run_command(cli() + " recognize --pen-radius 2 --tolerance 10 " + strokes +
                                  " --json"); // epsilon 10: the bend moved below is 2 epsilon
  ASSERT_EQ(rec.exit_code, 0) << rec.out;
  ASSERT_NE(rec.out.find("\"class\":\"arrow\""), std::string::npos) << rec.out;
  const auto b = rec.out.find("\"shaft_bends\":[[");
  ASSERT_NE(b, std::string::npos) << rec.out;
  const std::string answer = write("hockey_stick.json", rec.out);
  const Result ok = penshape::test::run_command(cli() + " verify " + strokes + " " + answer);
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  // The bend moved 20 (2 epsilon) down, away from the corner's inside (the shaft turns up).
  const auto y = rec.out.find(',', b) + 1;
  const auto y_end = rec.out.find(']', y);
  const double by = std::stod(rec.out.substr(y, y_end - y));
  const std::string moved =
      rec.out.substr(0, y) + std::to_string(by + 20.0) + rec.out.substr(y_end);
  const Result bad = penshape::test::run_command(cli() + " verify " + strokes + " " +
                                                 write("hockey_stick_moved.json", moved));
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
}

// An arrow drawn as a shaft stroke that stops 45 short of the head's tip (0.9 barbs, about 3
// epsilon): `recognize --json` answers one arrow of both strokes whose shaft ends there
// ("shaft_end"), `verify` accepts it, and the same answer without its shaft_end (the shaft
// running on to the tip, across the gap) is refuted.
TEST(VerifyCli, ArrowWhoseShaftStopsShortVerifiesAndTheJoinedOneDoesNot) {
  const std::string strokes =
      write("gapped_arrow.jsonl",
            strokes_json({{{0, 0}, {110, 0}}, {{118, 57.4}, {200, 0}, {118, -57.4}}}));
  std::string answer;
  const Result ok = recognize_and_verify(strokes, &answer);
  ASSERT_NE(answer.find("\"lines\":[1,2]"), std::string::npos) << answer;
  ASSERT_NE(answer.find("\"class\":\"arrow\""), std::string::npos) << answer;
  const auto at = answer.find(",\"shaft_end\":[");
  ASSERT_NE(at, std::string::npos) << answer;
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_EQ(ok.out, "verified\n");
  const std::string joined = answer.substr(0, at) + answer.substr(answer.find(']', at) + 1);
  const Result bad = penshape::test::run_command(cli() + " verify " + strokes + " " +
                                                 write("gapped_arrow_joined.json", joined));
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
}

} // namespace

// An L-shaped hexagon in one stroke: `recognize --json` names it a `polygon` with its six
// corners, `verify` accepts the answer, and the same answer with a corner moved 80 to the right
// (epsilon is about 35) is refuted.
TEST(VerifyCli, PolygonAnswerVerifiesAndAMovedCornerDoesNot) {
  const std::string text =
      polyline_stroke_json({{0, 0}, {200, 0}, {200, 80}, {80, 80}, {80, 200}, {0, 200}, {0, 0}});
  const std::string strokes = write("l_hexagon.jsonl", text);
  std::string answer;
  const Result ok = recognize_and_verify(strokes, &answer);
  ASSERT_NE(answer.find("\"class\":\"polygon\""), std::string::npos) << answer;
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_EQ(ok.out, "verified\n");
  const auto v = answer.find("\"vertices\":[[") + 13;
  const auto comma = answer.find(',', v);
  const double x = std::stod(answer.substr(v, comma - v));
  const std::string moved = answer.substr(0, v) + std::to_string(x + 80.0) + answer.substr(comma);
  const Result bad = penshape::test::run_command(cli() + " verify " + strokes + " " +
                                                 write("l_hexagon_moved.json", moved));
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
}

// A flowchart diamond in one stroke (a rhombus of 67 and 113 degrees): `recognize --json` names it
// a `diamond` with its four corners and `verify` accepts the answer.
TEST(VerifyCli, DiamondAnswerVerifies) {
  const std::string text =
      polyline_stroke_json({{100, 0}, {200, 150}, {100, 300}, {0, 150}, {100, 0}});
  const std::string strokes = write("diamond.jsonl", text);
  std::string answer;
  const Result ok = recognize_and_verify(strokes, &answer);
  ASSERT_NE(answer.find("\"class\":\"diamond\""), std::string::npos) << answer;
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_EQ(ok.out, "verified\n");
}
