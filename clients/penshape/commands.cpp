// The table of `penshape` subcommands. A new subcommand: one file with its run function, one
// row here.
#include <array>

#include "command.hpp"
#include "deconstruct_command.hpp"
#include "version_command.hpp"

namespace penshape::cli {

std::span<const Subcommand> subcommands() {
  static constexpr std::array kCommands{
      Subcommand{"version", "print the version and the libraries penshape was built with",
                 &run_version},
      Subcommand{"deconstruct", "is a polygon file an approximate offset? (offset deconstruction)",
                 &run_deconstruct},
  };
  return kCommands;
}

} // namespace penshape::cli
