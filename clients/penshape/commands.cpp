// The table of `penshape` subcommands. A new subcommand: one file with its run function, one
// row here.
#include <array>

#include "command.hpp"
#include "recognize_command.hpp"
#include "version_command.hpp"

namespace penshape::cli {

std::span<const Subcommand> subcommands() {
  static constexpr std::array kCommands{
      Subcommand{"version", "print the version and the libraries penshape was built with",
                 &run_version},
      Subcommand{"recognize", "name the shape of pen strokes, snapping only with a certificate",
                 &run_recognize},
  };
  return kCommands;
}

} // namespace penshape::cli
