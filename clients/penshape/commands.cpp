// The table of `penshape` subcommands. A new subcommand: one file with its run function, one
// row here.
#include <array>

#include "command.hpp"
#include "deconstruct_command.hpp"
#include "hid_describe_command.hpp"
#include "live_commands.hpp"
#include "recognize_command.hpp"
#include "replay_command.hpp"
#include "search_commands.hpp"
#include "snap_command.hpp"
#include "synthesize_recording_command.hpp"
#include "verify_command.hpp"
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
      Subcommand{"hid tablets", "list the tablet table: family, physical size, maxima",
                 &run_hid_tablets},
      Subcommand{"replay", "decode a recorded tablet stream into strokes (shapes via penshaped)",
                 &run_replay},
      Subcommand{"deconstruct", "is a polygon file an approximate offset? (offset deconstruction)",
                 &run_deconstruct},
      Subcommand{"verify", "re-check deconstruct answers independently and exactly", &run_verify},
      Subcommand{"search-tolerance", "the smallest tolerance for a radius (ε̂ search, certified)",
                 &run_search_tolerance},
      Subcommand{"search-radius", "the radii that have a solution for a tolerance ([0, r*])",
                 &run_search_radius},
      Subcommand{"suggest-radius", "radii where r / ε̂(r) peaks, with their solutions",
                 &run_suggest_radius},
      Subcommand{"recognize", "name the shape of pen strokes, snapping only with a certificate",
                 &run_recognize},
      Subcommand{"snap", "snap the strokes of an SVG or Xournal++ drawing to clean shapes",
                 &run_snap},
      Subcommand{"synthesize-recording",
                 "write real strokes as a tablet's reports (a hid-recorder file)",
                 &run_synthesize_recording},
  };
  return kCommands;
}

} // namespace penshape::cli
