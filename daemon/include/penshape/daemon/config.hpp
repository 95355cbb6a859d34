#pragma once
// penshaped's configuration: a TOML file (read with toml++) with optional per-device tables.
//
//   # comments start with '#'; keys are unique per table
//   listen = "unix:/run/user/1000/penshape.sock"  # gRPC address (default: $XDG_RUNTIME_DIR/...)
//   tcp = "127.0.0.1:7433"           # also listen on TCP (default: off)
//   tcp_allow_non_loopback = false   # must be true for a tcp host other than loopback
//   max_message_bytes = 16777216     # and every other key of Limits (limits.hpp), integers
//   pen_radius_mm = 1.0              # default pen settings (pen_settings.hpp for the ranges)
//   tolerance_fraction = 0.5
//   precision_fraction = 0.125
//   snap_trigger = "both"            # pen_up, hold or both
//   grouping = true                  # group each tablet's recent strokes into one shape
//   group_max_strokes = 4            #  at most this many strokes in a group, 1..8
//   group_max_pause_s = 2.0          #  pen-up pause a group may span, seconds in [0, 60]
//   tidy_circle = true               # tidy-up switches (each applied only when certified):
//   tidy_right_angles = true         #  tidy_circle, tidy_right_angles, tidy_equal_sides,
//                                    #  tidy_axis, tidy_parallel, tidy_connection
//
//   [device."056a:0010"]             # settings for one tablet model (vendor:product, hex)
//   pen_radius_mm = 0.8
//   width_mm = 152.0                 # its active area, for a tablet that does not tell its
//   height_mm = 95.0                 #  size (both or neither; used only then)
//
// Numbers may be written as integers or decimals. Every error names the file, the line and the
// key; unknown keys are errors (typos must not pass silently). A file in the former format
// (`listen = unix:...` unquoted, `[device 056a:0010]`) is refused with, for each such line, what
// to write instead. With no file the defaults apply.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "penshape/daemon/grouping_settings.hpp"
#include "penshape/daemon/limits.hpp"
#include "penshape/daemon/pen_settings.hpp"

namespace penshape::daemon {

struct DaemonConfig {
  std::string listen; // "" = default_address()
  std::string tcp;    // "" = no TCP; else HOST:PORT
  bool tcp_allow_non_loopback = false;
  Limits limits;
  PenSettings settings;
  GroupingConfig grouping; // live strokes' grouping window and tidy-up switches
  std::map<std::string, PenSettingsUpdate> device_settings; // by device key "vvvv:pppp"
  // Physical sizes (width, height in mm) by device key, for tablets whose table row, descriptor
  // and probe give none: without one such a tablet's size is unknown (never device units as mm).
  std::map<std::string, std::pair<double, double>> device_sizes;
};

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses a config text; `origin` names it in messages ("penshaped.conf:12: ...").
DaemonConfig parse_config(std::string_view text, const std::string& origin);

// Reads and parses a file; throws ConfigError when it cannot be read or is invalid.
DaemonConfig load_config_file(const std::string& path);

// Checks a TCP address "HOST:PORT" (IPv4, [IPv6] or "localhost"); throws ConfigError unless the
// host is loopback or `allow_non_loopback` is set.
void validate_tcp_address(const std::string& address, bool allow_non_loopback);

} // namespace penshape::daemon
