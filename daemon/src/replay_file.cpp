// Loads and checks a --replay recording: every reason it cannot be played is found here, before
// the daemon starts, so the replay thread never meets a descriptor it cannot use.
#include "replay_file.hpp"

#include <exception>

#include "penshape/drivers/device_profile.hpp"

namespace penshape::daemon {

drivers::Recording load_replay_file(const std::string& path) {
  drivers::Recording recording;
  try {
    recording = drivers::load_recording_file(path);
  } catch (const drivers::RecordingError& e) {
    const std::string where =
        e.offset() > 0 ? " (at byte " + std::to_string(e.offset()) + ")" : std::string();
    throw BadReplayFile(path + ": " + e.what() + where);
  }
  if (recording.descriptor.empty()) {
    throw BadReplayFile(path + ": no report descriptor (an R: line) in the recording");
  }
  drivers::DeviceProfile profile;
  try {
    profile =
        drivers::build_profile(recording.identity, recording.descriptor, recording.vendor_strings);
  } catch (const std::exception& e) {
    throw BadReplayFile(path +
                        ": not a tablet recording (hid-recorder or usbhid-dump text, or a report "
                        "descriptor): " +
                        e.what());
  }
  if (!profile.has_pen()) {
    throw BadReplayFile(path + ": its report descriptor describes no pen");
  }
  if (recording.events.empty()) {
    throw BadReplayFile(path + ": no input reports (E: lines) to replay");
  }
  return recording;
}

} // namespace penshape::daemon
