// `penshape recognize` leaves writing alone (issue 24): every answer carries its intent in JSON
// and text, writing strokes are freeform answers of their own, and --snap-writing turns the
// filter off. On a generated page of notes (tests/core/intent/generated_ink.hpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/intent/generated_ink.hpp"
#include "run_command.hpp"

namespace {

penshape::test::CommandResult run(const std::string& args) {
  return penshape::test::run_command(std::string(PENSHAPE_CLI) + " recognize " + args);
}

// Two lines of cursive words with t-bars (dots left out: the file format wants 2 points), and
// the five generated shapes below the second line. Returns the file.
std::filesystem::path write_page() {
  auto path = std::filesystem::temp_directory_path() /
              ("penshape_intent_cli_" + std::to_string(::getpid()) + ".jsonl");
  std::ofstream out(path);
  for (const auto& s : penshape::test::ink::note_page(2, true)) {
    if (s.points.size() < 2) continue;
    nlohmann::json line;
    for (const auto& p : s.points) line["points"].push_back({p.x, p.y, p.t});
    line["label"] = s.writing ? "writing" : "drawing";
    out << line.dump() << "\n";
  }
  return path;
}

struct Counts {
  int answers = 0, writing = 0, writing_snapped = 0, drawing_snapped = 0;
};

Counts count(const std::string& out) {
  Counts c;
  std::istringstream lines(out);
  std::string text;
  while (std::getline(lines, text)) {
    const auto j = nlohmann::json::parse(text);
    ++c.answers;
    const bool writing = j.at("intent") == "writing";
    EXPECT_TRUE(writing || j.at("intent") == "drawing") << text;
    EXPECT_GE(j.at("writing_score").get<double>(), 0.0);
    const bool snapped = j.at("class") != "freeform";
    c.writing += writing ? 1 : 0;
    c.writing_snapped += writing && snapped ? 1 : 0;
    c.drawing_snapped += !writing && snapped ? 1 : 0;
  }
  return c;
}

TEST(RecognizeIntentCli, WritingIsNeverSnappedAndEveryAnswerSaysItsIntent) {
  const auto file = write_page();
  const auto r = run("--json --pen-radius 0.35 " + file.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const Counts c = count(r.out);
  EXPECT_GT(c.writing, 20);
  EXPECT_EQ(c.writing_snapped, 0);
  EXPECT_GE(c.drawing_snapped, 4) << r.out; // the shapes still snap
  const auto text = run("--pen-radius 0.35 " + file.string());
  EXPECT_NE(text.out.find("-> freeform (writing)"), std::string::npos) << text.out;
  std::filesystem::remove(file);
}

TEST(RecognizeIntentCli, SnapWritingTurnsTheFilterOff) {
  const auto file = write_page();
  const auto r = run("--json --snap-writing --pen-radius 0.35 " + file.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const Counts c = count(r.out);
  EXPECT_GT(c.writing_snapped, 0) << "the t-bars are clean segments"; // as before the filter
  EXPECT_NE(run("--help").out.find("--snap-writing"), std::string::npos);
  std::filesystem::remove(file);
}

} // namespace
