#pragma once
// Where a bench's outside data lives: the shared corpus (../shared/data beside the clone, never
// copied into the repository) or the folder $PENSHAPE_SHARED_DATA_DIR names. Every bench that
// reads it says on stderr which data it used, so a figure is never quoted without its source.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace penshape::bench {

// $PENSHAPE_SHARED_DATA_DIR when set and not empty, else the configured shared data folder.
inline std::string shared_data_dir() {
  const char* env = std::getenv("PENSHAPE_SHARED_DATA_DIR");
  return env != nullptr && *env != 0 ? std::string(env) : std::string(PENSHAPE_SHARED_DATA_DIR);
}

// "<bench>: data: <what>" on stderr.
inline void say_data(const char* bench, const std::string& what) {
  std::fprintf(stderr, "%s: data: %s\n", bench, what.c_str());
}

} // namespace penshape::bench
