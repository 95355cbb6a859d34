// `penshape synthesize-recording` then `penshape replay --local`: the strokes come back.
#include <gtest/gtest.h>

#include <string>

#include "run_command.hpp"
#include "test_data.hpp"

namespace {

using penshape::test::data_file;
using penshape::test::run_command;

std::string cli(const std::string& args) { return std::string(PENSHAPE_CLI) + " " + args; }

const std::string kDescriptor = data_file(
    "hid/wacom-hid-descriptors/XP_Pen_Deco01_V2/sysinfo.FIpgWPPUGW/0003:28BD:0905.0033.hid.bin");

TEST(SynthesizeCli, StrokesReplayBack) {
  const std::string out = std::string(PENSHAPE_BINARY_DIR) + "/synthesized_test.hidrec";
  const auto made = run_command(cli("synthesize-recording --descriptor '" + kDescriptor +
                                    "' --vid 28bd --pid 0905 --out " + out + " " +
                                    data_file("strokes/dollar1/s02/medium/circle01.xml") + " " +
                                    data_file("strokes/dollar1/s03/fast/triangle02.xml")));
  ASSERT_EQ(made.exit_code, 0) << made.out;
  EXPECT_NE(made.out.find("2 strokes"), std::string::npos) << made.out;
  const auto replayed = run_command(cli("replay --local " + out));
  ASSERT_EQ(replayed.exit_code, 0) << replayed.out;
  EXPECT_NE(replayed.out.find("stroke 2:"), std::string::npos) << replayed.out;
  EXPECT_EQ(replayed.out.find("stroke 3:"), std::string::npos) << replayed.out;
}

TEST(SynthesizeCli, BadInputExitsTwo) {
  EXPECT_EQ(run_command(cli("synthesize-recording --descriptor /nonexistent --vid 1 --pid 2 "
                            "--out /tmp/x.hidrec " +
                            data_file("strokes/dollar1/s02/medium/circle01.xml")))
                .exit_code,
            2);
  EXPECT_EQ(run_command(cli("synthesize-recording --descriptor '" + kDescriptor +
                            "' --vid zz --pid 2 --out /tmp/x.hidrec a.xml"))
                .exit_code,
            2);
  EXPECT_EQ(run_command(cli("synthesize-recording --descriptor '" + kDescriptor +
                            "' --vid 1 --pid 2 --out /tmp/x.hidrec /nonexistent.xml"))
                .exit_code,
            2);
}

} // namespace
