#include "args.hpp"

#include <gtest/gtest.h>

#include <array>

namespace penshape::cli {
namespace {

const ArgSpec kSpec{.flags = {"--json"}, .options = {"--radius", "--tolerance"}};

TEST(Args, ParsesFlagsOptionsAndPositionals) {
  const std::array<std::string_view, 6> argv{"a.txt",  "--radius",        "2.5",
                                             "--json", "--tolerance=0.1", "b.txt"};
  const ParsedArgs args(argv, kSpec);
  EXPECT_TRUE(args.flag("--json"));
  EXPECT_EQ(args.number("--radius"), 2.5);
  EXPECT_EQ(args.number("--tolerance"), 0.1);
  EXPECT_FALSE(args.value("--missing"));
  EXPECT_EQ(args.positionals(), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(Args, RejectsBadUsage) {
  const std::array<std::string_view, 1> unknown{"--nope"};
  EXPECT_THROW(ParsedArgs(unknown, kSpec), UsageError);
  const std::array<std::string_view, 1> missing{"--radius"};
  EXPECT_THROW(ParsedArgs(missing, kSpec), UsageError);
  const std::array<std::string_view, 1> flag_value{"--json=1"};
  EXPECT_THROW(ParsedArgs(flag_value, kSpec), UsageError);
  const std::array<std::string_view, 1> short_opt{"-x"};
  EXPECT_THROW(ParsedArgs(short_opt, kSpec), UsageError);
  for (const char* bad : {"nan", "inf", "1e999", "2x", ""}) {
    const std::array<std::string_view, 2> argv{"--radius", bad};
    const ParsedArgs args(argv, kSpec);
    EXPECT_THROW((void)args.number("--radius"), UsageError) << bad;
  }
}

TEST(Args, DoubleDashEndsOptions) {
  const std::array<std::string_view, 2> argv{"--", "--json"};
  const ParsedArgs args(argv, kSpec);
  EXPECT_FALSE(args.flag("--json"));
  EXPECT_EQ(args.positionals(), (std::vector<std::string>{"--json"}));
}

} // namespace
} // namespace penshape::cli
