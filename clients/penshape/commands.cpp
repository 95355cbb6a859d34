// The table of `penshape` subcommands. A new subcommand: one file with its run function, one
// row here.
#include <array>

#include "command.hpp"
#include "deconstruct_command.hpp"
#include "hid_describe_command.hpp"
#include "live_commands.hpp"
#include "replay_command.hpp"
#include "version_command.hpp"

namespace penshape::cli {

std::span<const Subcommand> subcommands() {
  static constexpr std::array kCommands{
      Subcommand{"version", "print the version and the libraries penshape was built with",
                 &run_version},
      Subcommand{"devices", "list the tablets penshaped reads (live)", &run_devices},
      Subcommand{"watch", "print strokes and shapes as they are drawn (live)", &run_watch},
      Subcommand{"record", "record a tablet's pen samples to a hid-recorder file (live)",
                 &run_record},
      Subcommand{"hid describe", "print a HID report descriptor's layouts and pen fields",
                 &run_hid_describe},
      Subcommand{"replay", "decode a recorded tablet stream into samples and strokes (--local)",
                 &run_replay},
      Subcommand{"deconstruct", "is a polygon file an approximate offset? (offset deconstruction)",
                 &run_deconstruct},
  };
  return kCommands;
}

} // namespace penshape::cli
