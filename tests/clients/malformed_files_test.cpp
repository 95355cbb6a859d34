// Every kind of file the programs read, malformed in the ways real files are (empty, truncated,
// garbage, NaN, absurd numbers, the wrong format): the real `penshape` answers exit 2 with a
// message naming the file, never a crash, and leaves no output file behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "test_data.hpp"

namespace {

namespace fs = std::filesystem;

struct Case {
  std::string name;    // file name (its extension picks the stroke format)
  std::string content; // the file's bytes
  std::string command; // the subcommand and options before FILE
};

class MalformedFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "penshape-malformed-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes the file, runs the command on it and checks the outcome.
  void expect_bad_input(const Case& c) {
    SCOPED_TRACE(c.command + " " + c.name);
    const fs::path file = dir_ / c.name;
    std::ofstream(file, std::ios::binary) << c.content;
    const auto r = penshape::test::run_command(std::string(PENSHAPE_CLI) + " " + c.command + " '" +
                                               file.string() + "' 2>&1");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find(c.name), std::string::npos) << "the message names the file: " << r.out;
    EXPECT_EQ(r.out.find("internal error"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("terminate called"), std::string::npos) << r.out;
  }

  fs::path dir_;
};

TEST_F(MalformedFiles, PolygonFiles) {
  for (const char* command : {"deconstruct --radius 1 --tolerance 0.5",
                              "search-tolerance --radius 1", "search-radius --tolerance 0.5"}) {
    for (const Case& c : std::vector<Case>{
             {"empty.txt", "", command},
             {"word.txt", "0 0\n4 0\n4 x\n", command},
             {"one-number.txt", "0 0\n4\n4 4\n", command},
             {"nan.txt", "0 0\nnan 0\n4 4\n", command},
             {"inf.txt", "0 0\n1e400 0\n4 4\n", command},
             {"bowtie.txt", "0 0\n4 4\n4 0\n0 4\n", command},
             {"two-points.txt", "0 0\n4 4\n", command},
             {"truncated.wkt", "POLYGON((0 0, 4 0, 4 4", command},
             {"garbage.bin", std::string("\x00\xff\x13\x37 \x01", 6), command},
         }) {
      expect_bad_input(c);
    }
  }
}

TEST_F(MalformedFiles, StrokeFiles) {
  const std::string command = "recognize --json";
  for (const Case& c : std::vector<Case>{
           {"empty-points.jsonl", "{\"points\": []}\n", command},
           {"not-json.jsonl", "{\"points\": [[0, 0, 0], [1, 1\n", command},
           {"nan.jsonl", "{\"points\": [[0, 0, 0], [NaN, 1, 0.1], [2, 2, 0.2]]}\n", command},
           {"strings.jsonl", "{\"points\": [[\"a\", 0, 0], [1, 1, 0.1]]}\n", command},
           {"no-points.jsonl", "{\"name\": \"x\"}\n", command},
           {"truncated.xml", "<Gesture Name=\"circle01\"><Point X=\"1\" Y=", command},
           {"no-points.xml", "<Gesture Name=\"circle01\"></Gesture>\n", command},
           {"garbage.xml", std::string("\xff\xfe\x00<", 4), command},
       }) {
    expect_bad_input(c);
  }
}

TEST_F(MalformedFiles, TabletRecordingsAndDescriptors) {
  const std::string recording =
      penshape::test::read_file(penshape::test::recordings_dir() / "generated-graphire.hidrec");
  const std::string header = recording.substr(0, recording.find("E: "));
  for (const char* command : {"replay --local", "hid describe"}) {
    for (const Case& c : std::vector<Case>{
             {"empty.hidrec", "", command},
             {"bad-hex.hidrec", "R: 4 05 0d zz 02\n", command},
             {"short.hidrec", "R: 9 05 0d 09 02\n", command},
             {"bad-descriptor.bin", std::string("\x05\x0d\x09\x02\xa1\x01\xff\xff", 8), command},
             {"text.hidrec", "hello, this is not a recording\n", command},
         }) {
      expect_bad_input(c);
    }
  }
  // A recording cut inside an event line, and one with no events at all.
  expect_bad_input({"cut.hidrec", header + "E: 000000.000000 8 02 f", "replay --local"});
  expect_bad_input({"no-events.hidrec", header, "replay --local"});
}

// A command that writes a file (an SVG picture) leaves none when its input is bad.
TEST_F(MalformedFiles, NoPartialOutputOnBadInput) {
  const fs::path out = dir_ / "out.svg";
  std::ofstream(dir_ / "bad.txt") << "0 0\n4 x\n";
  const auto r = penshape::test::run_command(
      std::string(PENSHAPE_CLI) + " deconstruct --radius 1 --tolerance 0.5 --svg '" + out.string() +
      "' '" + (dir_ / "bad.txt").string() + "' 2>&1");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

} // namespace
