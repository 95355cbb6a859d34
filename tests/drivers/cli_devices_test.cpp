// `penshape hid describe` and `penshape replay --local`, run as a user would, on real files.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>

#include "shared_data.hpp"

namespace {

struct Result {
  int exit_code = -1;
  std::string out;
};

Result run(const std::string& args) {
  const std::string cmd = std::string(PENSHAPE_CLI) + " " + args + " 2>&1";
  Result r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) r.out += buf.data();
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string data(const std::string& rel) {
  std::string quoted = "'";
  quoted += (penshape::drivers::testing::hid_dir() / rel).string();
  quoted += "'";
  return quoted;
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(CliDevices, DescribeJsonHasTheIssueKeys) {
  // Huion HS610 firmware-mode pen interface: report 0x0A, 16-bit X/Y with a physical size.
  const Result r =
      run("hid describe --json " +
          data("wacom-hid-descriptors/Huion_HS610/sysinfo.MGYZr3MuFs/0003:256C:0064.001B.hid.bin"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.rfind("{\"reports\":[{\"id\":", 0), 0U) << r.out;
  for (const char* key :
       {"\"fields\":", "\"usage\":\"Digitizer/Tip Switch\"", "\"bit_offset\":8",
        "\"size\":", "\"logical_min\":", "\"logical_max\":", "\"pen\":{\"report_id\":10",
        "\"x_max\":", "\"y_max\":", "\"pressure_max\":8191", "\"resolution\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << r.out;
  }
}

TEST(CliDevices, DescribeVendorProtocolFromTheIdLine) {
  const Result r =
      run("hid describe " + data("wacom-hid-descriptors/Wacom_PenPartner/hidrecord.txt"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("pen (wacom-graphire protocol): x_max 3250, y_max 2320"), std::string::npos)
      << r.out;
}

TEST(CliDevices, ReplayJsonSamplesAndStrokes) {
  const Result r =
      run("replay --local --json " + data("wacom-hid-descriptors/Wacom_PenPartner/hidrecord.txt"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(count(r.out, "{\"t\":"), 757U);
  EXPECT_EQ(count(r.out, "{\"stroke\":"), 3U);
  for (const char* key :
       {"\"x\":", "\"y\":", "\"pressure\":", "\"tilt_x\":", "\"tilt_y\":", "\"tip\":true",
        "\"in_range\":", "\"buttons\":", "\"t_start\":", "\"t_end\":", "\"samples\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  }
}

TEST(CliDevices, ReplayUsbhidDumpWithVidPidAndDescriptor) {
  const Result r = run("replay --local --json --vid 28bd --pid 0042 --descriptor " +
                       data("digimend-tablets/XP-Pen_Deco_01/rd/original1.txt") + " " +
                       data("digimend-tablets/XP-Pen_Deco_01/dumps/pen_pressure.txt"));
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
  EXPECT_EQ(run("replay " + bad).exit_code, 2);                    // --local missing
}

} // namespace
