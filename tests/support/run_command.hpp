#pragma once
// Runs a command line through the shell, as a user would, capturing stdout and stderr.
#include <string>

namespace penshape::test {

struct CommandResult {
  int exit_code = -1; // -1 when the command did not exit normally
  std::string out;    // stdout and stderr, interleaved
};

CommandResult run_command(const std::string& command_line);

} // namespace penshape::test
