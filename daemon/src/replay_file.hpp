#pragma once
// The recording `penshaped --replay FILE` plays, read and checked whole before the daemon serves:
// a file that is not a tablet recording is bad input (exit 2) named with its reason, never a
// failure after the socket exists.
#include <stdexcept>
#include <string>

#include "penshape/drivers/recording.hpp"

namespace penshape::daemon {

struct BadReplayFile : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The recording at `path` (hid-recorder or usbhid-dump text), with a report descriptor that
// parses and describes a pen, and at least one input report. Throws BadReplayFile naming the
// file and what is wrong with it.
drivers::Recording load_replay_file(const std::string& path);

} // namespace penshape::daemon
