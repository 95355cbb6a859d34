// `penshape synthesize-recording` then `penshape replay --local`: the strokes come back, on a
// descriptor that describes its pen and on a vendor-protocol tablet known by VID:PID. Strokes and
// descriptors are generated (tests/support/gen).
#include <gtest/gtest.h>

#include <string>

#include "descriptor_gen.hpp"
#include "generated_files.hpp"
#include "run_command.hpp"
#include "test_data.hpp"

namespace {

using penshape::test::run_command;
using penshape::testing::stroke_file;
using penshape::testing::write_generated;

std::string cli(const std::string& args) { return std::string(PENSHAPE_CLI) + " " + args; }

std::string descriptor_file(const std::string& name, const std::vector<std::uint8_t>& bytes) {
  return write_generated(name, std::string(bytes.begin(), bytes.end()));
}

const std::string kDescriptor =
    descriptor_file("pen_descriptor.bin",
                    penshape::gen::pen_descriptor(penshape::gen::pen_descriptor_specs().front()));

TEST(SynthesizeCli, StrokesReplayBack) {
  const std::string out = std::string(PENSHAPE_BINARY_DIR) + "/synthesized_test.hidrec";
  const auto made = run_command(cli("synthesize-recording --descriptor '" + kDescriptor +
                                    "' --vid 1209 --pid 7e50 --out " + out + " " +
                                    stroke_file("circle", 1) + " " + stroke_file("triangle", 2)));
  ASSERT_EQ(made.exit_code, 0) << made.out;
  EXPECT_NE(made.out.find("2 strokes"), std::string::npos) << made.out;
  const auto replayed = run_command(cli("replay --local " + out));
  ASSERT_EQ(replayed.exit_code, 0) << replayed.out;
  EXPECT_NE(replayed.out.find("stroke 2:"), std::string::npos) << replayed.out;
  EXPECT_EQ(replayed.out.find("stroke 3:"), std::string::npos) << replayed.out;
}

// A tablet whose descriptor leaves the pen report vendor-defined: the drivers' profile for its
// VID:PID (Wacom's Graphire protocol for 056a:0061, sized by the tablet table) writes the reports.
TEST(SynthesizeCli, VendorProtocolTabletsAreWrittenInTheirProtocol) {
  const std::string vendor =
      descriptor_file("vendor_descriptor.bin", penshape::gen::vendor_pen_descriptor(2, 8));
  const std::string out = std::string(PENSHAPE_BINARY_DIR) + "/synthesized_graphire_test.hidrec";
  const auto made = run_command(cli("synthesize-recording --descriptor '" + vendor +
                                    "' --vid 056a --pid 0061 --rate 125 --out " + out + " " +
                                    stroke_file("square", 5)));
  ASSERT_EQ(made.exit_code, 0) << made.out;
  const auto replayed = run_command(cli("replay --local " + out));
  ASSERT_EQ(replayed.exit_code, 0) << replayed.out;
  EXPECT_NE(replayed.out.find("family wacom-graphire"), std::string::npos) << replayed.out;
  EXPECT_NE(replayed.out.find("stroke 1:"), std::string::npos) << replayed.out;
  EXPECT_EQ(replayed.out.find("stroke 2:"), std::string::npos) << replayed.out;
  // Without a VID:PID the drivers know, the same descriptor has no pen.
  EXPECT_EQ(
      run_command(cli("synthesize-recording --descriptor '" + vendor +
                      "' --vid 1209 --pid 7e51 --out " + out + " " + stroke_file("square", 5)))
          .exit_code,
      2);
}

TEST(SynthesizeCli, BadInputExitsTwo) {
  EXPECT_EQ(run_command(cli("synthesize-recording --descriptor /nonexistent --vid 1 --pid 2 "
                            "--out /tmp/x.hidrec " +
                            stroke_file("circle", 1)))
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
