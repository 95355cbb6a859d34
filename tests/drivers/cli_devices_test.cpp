// `penshape hid describe` and `penshape replay --local`, run as a user would, on real files (the
// shared corpus, skipped without it) and on the project's generated descriptors and recordings.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "descriptor_gen.hpp"
#include "run_command.hpp"
#include "shared_data.hpp"

namespace {

using Result = penshape::test::CommandResult;

Result run(const std::string& args) {
  return penshape::test::run_command(std::string(PENSHAPE_CLI) + " " + args);
}

std::string quoted(const std::filesystem::path& path) {
  std::string out = "'"; // built by appending: g++ 12 warns falsely (-Wrestrict) on "'" + string
  out += path.string();
  out += "'";
  return out;
}

// The generated recording in the PenPartner's protocol (Wacom Graphire, 056a:0061).
std::string penpartner() { return quoted(penshape::drivers::testing::penpartner_capture()); }

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

void expect_issue_keys(const std::string& descriptor, const std::string& pen_report_id) {
  const Result r = run("hid describe --json " + descriptor);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.rfind("{\"reports\":[{\"id\":", 0), 0U) << r.out;
  const std::string pen = "\"pen\":{\"report_id\":" + pen_report_id;
  for (const char* key : {"\"fields\":", "\"usage\":\"Digitizer/Tip Switch\"", "\"bit_offset\":8",
                          "\"size\":", "\"logical_min\":", "\"logical_max\":", pen.c_str(),
                          "\"x_max\":", "\"y_max\":", "\"pressure_max\":8191", "\"resolution\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
}

TEST(CliDevices, DescribeJsonHasTheIssueKeys) {
  // Huion HS610 firmware-mode pen interface: report 0x0A, 16-bit X/Y with a physical size.
  PENSHAPE_SHARED_OR_SKIP(
      bin, "hid/wacom-hid-descriptors/Huion_HS610/sysinfo.MGYZr3MuFs/0003:256C:0064.001B.hid.bin");
  expect_issue_keys(quoted(bin), "10");
}

TEST(CliDevices, DescribeJsonHasTheIssueKeysOnAGeneratedDescriptor) {
  // The project's own pen descriptor: report 7, 16-bit X/Y in centimetres, 8191 pressure levels.
  const std::string bin = ::testing::TempDir() + "/penshape_generated_descriptor.bin";
  const auto bytes = penshape::gen::pen_descriptor(penshape::gen::pen_descriptor_specs().front());
  std::ofstream(bin, std::ios::binary) << std::string(bytes.begin(), bytes.end());
  expect_issue_keys(bin, "7");
}

TEST(CliDevices, DescribeVendorProtocolFromTheIdLine) {
  const Result r = run("hid describe " + penpartner());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("pen (wacom-graphire protocol): x_max 3250, y_max 2320"), std::string::npos)
      << r.out;
}

void expect_json_samples_and_strokes(const std::string& recording, std::size_t samples,
                                     std::size_t strokes) {
  const Result r = run("replay --local --json " + recording);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(count(r.out, "{\"t\":"), samples);
  EXPECT_EQ(count(r.out, "{\"stroke\":"), strokes);
  for (const char* key :
       {"\"x\":", "\"y\":", "\"pressure\":", "\"tilt_x\":", "\"tilt_y\":", "\"tip\":true",
        "\"in_range\":", "\"buttons\":", "\"t_start\":", "\"t_end\":", "\"samples\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  }
}

TEST(CliDevices, ReplayJsonSamplesAndStrokes) {
  PENSHAPE_SHARED_OR_SKIP(capture, penshape::drivers::testing::kPenPartnerCapture);
  expect_json_samples_and_strokes(quoted(capture), 757U, 3U); // the real PenPartner capture
}

TEST(CliDevices, ReplayJsonSamplesAndStrokesOfAGeneratedRecording) {
  expect_json_samples_and_strokes(penpartner(), 653U, 3U);
}

TEST(CliDevices, ReplayUsbhidDumpWithVidPidAndDescriptor) {
  PENSHAPE_SHARED_OR_SKIP(deco01, "hid/digimend-tablets/XP-Pen_Deco_01");
  const Result r =
      run("replay --local --json --vid 28bd --pid 0042 --descriptor " +
          quoted(deco01 / "rd/original1.txt") + " " + quoted(deco01 / "dumps/pen_pressure.txt"));
  ASSERT_EQ(r.exit_code, 0) << r.out.substr(0, 400);
  EXPECT_EQ(count(r.out, "{\"t\":"), 1125U);
  EXPECT_EQ(count(r.out, "{\"stroke\":"), 1U);
}

TEST(CliDevices, MalformedInputExitsTwoNamingTheByteOffset) {
  const std::string bad = ::testing::TempDir() + "/penshape_bad_record.txt";
  std::ofstream(bad) << "R: 2 05 0d\nE: 0.000001 2 02 zz\n";
  Result r = run("replay --local " + bad);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("byte 28"), std::string::npos) << r.out;
  r = run("hid describe " + bad);
  EXPECT_EQ(r.exit_code, 2);
  const std::string truncated = ::testing::TempDir() + "/penshape_bad_descriptor.bin";
  std::ofstream(truncated, std::ios::binary) << std::string("\x05\x01\x26\xff", 4);
  r = run("hid describe " + truncated);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("byte 2"), std::string::npos) << r.out;
  EXPECT_EQ(run("replay --local /nonexistent/file").exit_code, 2);
  EXPECT_EQ(run("replay --local --vid 28bd " + bad).exit_code, 2); // --pid missing
  EXPECT_EQ(run("replay " + bad).exit_code, 2);                    // through penshaped or not
}

} // namespace

namespace {

TEST(CliTablets, ListsTheTableWithFamilyAndSize) {
  const Result all = run("hid tablets");
  ASSERT_EQ(all.exit_code, 0) << all.out;
  // One line per row plus the header; the PenPartner (Linux wacom driver facts: 3250 units at
  // 50 per mm = 65 mm) and the XP-Pen Deco 01 V2 (OTD: 254 x 158.75 mm, firmware 2020-10-23).
  EXPECT_GE(count(all.out, "\n"), 500U);
  EXPECT_NE(all.out.find("056a 0061 wacom-graphire"), std::string::npos) << all.out;
  const Result json = run("hid tablets --json --vid 28BD");
  ASSERT_EQ(json.exit_code, 0) << json.out;
  EXPECT_EQ(count(json.out, "\"vid\":\"28bd\""), count(json.out, "\n"));
  EXPECT_NE(
      json.out.find("{\"vid\":\"28bd\",\"pid\":\"0905\",\"name\":\"XP-Pen Deco 01 V2 (Variant 2)\","
                    "\"family\":\"xppen\",\"width_mm\":254,\"height_mm\":158.75,"
                    "\"max_x\":50800,\"max_y\":31750,\"max_pressure\":8191}"),
      std::string::npos)
      << json.out;
  EXPECT_EQ(run("hid tablets --vid nothex").exit_code, 2);
  EXPECT_EQ(run("hid tablets some-file").exit_code, 2);
}

TEST(CliTablets, DescribeAndReplayNameFamilyAndSizeSource) {
  // The generated default recording (the project's descriptor with physical units, on a
  // VID:PID the table does not know): every clone.
  const std::string rec = quoted(penshape::test::recordings_dir() / "generated-shapes.hidrec");
  const Result d = run("hid describe --json " + rec);
  ASSERT_EQ(d.exit_code, 0) << d.out;
  for (const char* key : {"\"family\":\"hid\"", "\"physical_size_known\":true", "\"width_mm\":224",
                          "\"height_mm\":140", "\"size_source\":\"descriptor\""}) {
    EXPECT_NE(d.out.find(key), std::string::npos) << key << " in " << d.out;
  }
  const Result r = run("replay --local " + rec);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("# family hid (layout hid), size 224.0 x 140.0 mm from the descriptor"),
            std::string::npos)
      << r.out.substr(0, 400);
}

} // namespace
