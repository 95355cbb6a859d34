// Runs the real `penshape` binary as a user would.
#include <gtest/gtest.h>

#include "run_command.hpp"

#include <array>
#include <cstdio>
#include <string>

namespace {

using Result = penshape::test::CommandResult;

Result run(const std::string& args) {
  return penshape::test::run_command(std::string(PENSHAPE_CLI) + " " + args);
}

TEST(Cli, HelpListsSubcommands) {
  const Result r = run("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("subcommands:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("version"), std::string::npos) << r.out;
}

TEST(Cli, NoArgumentsIsUsageError) { EXPECT_EQ(run("").exit_code, 2); }

TEST(Cli, UnknownSubcommandIsUsageError) {
  const Result r = run("frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown subcommand 'frobnicate'"), std::string::npos) << r.out;
}

TEST(Cli, VersionJson) {
  const Result r = run("version --json");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("{\"version\":\"", 0), 0U) << r.out;
  EXPECT_NE(r.out.find("CGAL 5."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hidapi"), std::string::npos) << r.out;
}

TEST(Cli, BadOptionIsUsageError) {
  const Result r = run("version --bogus");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown option '--bogus'"), std::string::npos) << r.out;
}

} // namespace
