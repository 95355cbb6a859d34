// libFuzzer: arbitrary bytes as the file of `penshaped --replay FILE`. Loading must accept it or
// throw BadReplayFile (which the daemon turns into exit 2 before it serves); an accepted
// recording must then replay through the drivers' decode path, the one the daemon's replay
// thread runs, without any exception.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "penshape/drivers/replay.hpp"
#include "replay_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = "/tmp/penshape-fuzz-" + std::to_string(::getpid()) + ".hidrec";
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  }
  try {
    const auto recording = penshape::daemon::load_replay_file(path);
    (void)penshape::drivers::replay(recording, penshape::drivers::ReplaySpeed::kAsFastAsPossible);
  } catch (const penshape::daemon::BadReplayFile&) {
  }
  std::remove(path.c_str());
  return 0;
}
