// Runs the real `penshape` binary as a user would.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

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
