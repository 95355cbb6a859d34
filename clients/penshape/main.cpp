// penshape: the command-line client. Offline subcommands work on files with the core library;
// live ones talk to penshaped.
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "args.hpp"
#include "command.hpp"
#include "version_command.hpp"

namespace {

void print_help() {
  std::puts("usage: penshape <subcommand> [options]\n\nsubcommands:");
  for (const auto& c : penshape::cli::subcommands()) {
    std::printf("  %-22s %s\n", std::string(c.name).c_str(), std::string(c.summary).c_str());
  }
  std::puts("\nEvery subcommand takes --help. Exit codes: 0 ok, 2 bad input, 1 internal failure.");
}

} // namespace

int main(int argc, char** argv) {
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help();
    return args.empty() ? penshape::cli::kExitBadInput : penshape::cli::kExitOk;
  }
  if (args[0] == "--version" && args.size() == 1) return penshape::cli::run_version({});
  // Longest match first, so "hid describe" wins over a hypothetical "hid".
  const penshape::cli::Subcommand* best = nullptr;
  std::size_t best_words = 0;
  for (const auto& c : penshape::cli::subcommands()) {
    std::size_t words = 0;
    std::string joined;
    for (std::size_t i = 0; i < args.size(); ++i) {
      joined += (i ? " " : "");
      joined += args[i];
      if (joined == c.name) {
        words = i + 1;
        break;
      }
    }
    if (words > best_words) {
      best = &c;
      best_words = words;
    }
  }
  if (best == nullptr) {
    std::fprintf(stderr, "penshape: unknown subcommand '%s' (see penshape --help)\n",
                 std::string(args[0]).c_str());
    return penshape::cli::kExitBadInput;
  }
  try {
    return best->run(std::span(args).subspan(best_words));
  } catch (const penshape::cli::UsageError& e) {
    std::fprintf(stderr, "penshape %s: %s (see --help)\n", std::string(best->name).c_str(),
                 e.what());
    return penshape::cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "penshape %s: internal error: %s\n", std::string(best->name).c_str(),
                 e.what());
    return penshape::cli::kExitInternal;
  }
}
