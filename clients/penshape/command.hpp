#pragma once
// A `penshape` subcommand: a name, a one-line summary, and a function taking its arguments.
// Exit codes every subcommand keeps: 0 ok, 2 bad input (usage, unreadable or malformed file),
// 1 internal failure.
#include <span>
#include <string_view>

namespace penshape::cli {

enum ExitCode : int { kExitOk = 0, kExitInternal = 1, kExitBadInput = 2 };

struct Subcommand {
  std::string_view name;    // may contain a space for nested commands, e.g. "hid describe"
  std::string_view summary; // one line for `penshape --help`
  int (*run)(std::span<const std::string_view> args); // args after the subcommand's name
};

// Every subcommand, in the order `penshape --help` lists them (commands.cpp).
std::span<const Subcommand> subcommands();

} // namespace penshape::cli
