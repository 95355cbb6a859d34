#pragma once
// Shared by the offline device subcommands: load a recording or descriptor file, with --vid and
// --pid standing in for a missing I: line and --descriptor FILE for a missing R: line.
#include <string>

#include "args.hpp"
#include "penshape/drivers/recording.hpp"

namespace penshape::cli {

// Loads FILE (the single positional). Malformed files throw drivers::RecordingError.
drivers::Recording load_device_file(const ParsedArgs& args);

// The FILE the command was given, for error messages ("" when there is none).
std::string device_file_name(const ParsedArgs& args);

} // namespace penshape::cli
