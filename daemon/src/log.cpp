#include "log.hpp"

#include <cstdio>
#include <cstdlib>

namespace penshape::daemon {

void log(LogLevel level, const std::string& message) {
  static const bool journal = std::getenv("JOURNAL_STREAM") != nullptr;
  // One fprintf per line so lines from different threads do not interleave.
  if (journal) {
    std::fprintf(stderr, "<%d>%s\n", static_cast<int>(level), message.c_str());
  } else {
    std::fprintf(stderr, "penshaped: %s\n", message.c_str());
  }
}

} // namespace penshape::daemon
