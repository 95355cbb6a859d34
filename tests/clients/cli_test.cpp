// Runs the real `penshape` binary as a user would.
#include <gtest/gtest.h>

#include "run_command.hpp"

#include <array>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

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

TEST(Cli, VersionOption) {
  const Result r = run("--version");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.rfind("penshape ", 0), 0U) << r.out;
}

// Every subcommand `penshape --help` lists answers -h and --help with its usage, exit 0.
TEST(Cli, EverySubcommandAnswersShortAndLongHelp) {
  const Result list = run("--help");
  std::vector<std::string> names;
  std::istringstream lines(list.out);
  for (std::string line; std::getline(lines, line);) {
    if (line.size() > 24 && line.rfind("  ", 0) == 0 && line[2] != ' ') {
      std::string name = line.substr(2, 22);
      name.erase(name.find_last_not_of(' ') + 1);
      names.push_back(name);
    }
  }
  ASSERT_GE(names.size(), 12U) << list.out;
  for (const std::string& name : names) {
    for (const char* help : {"-h", "--help"}) {
      const Result r = run(name + " " + help);
      EXPECT_EQ(r.exit_code, 0) << name << " " << help << ": " << r.out;
      EXPECT_NE(r.out.find("usage: penshape " + name), std::string::npos)
          << name << " " << help << ": " << r.out;
    }
  }
}

TEST(Cli, BadOptionIsUsageError) {
  const Result r = run("version --bogus");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown option '--bogus'"), std::string::npos) << r.out;
}

} // namespace
