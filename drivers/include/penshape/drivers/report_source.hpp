#pragma once
// Where a device's raw reports come from: a live hidraw node, a recording being replayed, or a
// fake in tests. The reader loop (pen_pipeline.hpp) is the same for all of them.
#include <chrono>
#include <cstdint>
#include <vector>

namespace penshape::drivers {

enum class ReadStatus : std::uint8_t {
  kReport,  // `bytes` and `time_us` hold the next report
  kTimeout, // nothing within the timeout (the loop uses it to expire debounce windows)
  kEnd,     // the source is exhausted (end of a recording)
  kGone,    // the device vanished (unplugged, suspended, read error)
};

class ReportSource {
 public:
  virtual ~ReportSource() = default;
  // Blocks up to `timeout` for the next report. `time_us` is on the source's own monotonic
  // clock (microseconds since the source started). Must not busy-wait.
  virtual ReadStatus read(std::vector<std::uint8_t>& bytes, std::int64_t& time_us,
                          std::chrono::milliseconds timeout) = 0;
  // The source's clock now (for idle timeouts), same epoch as `time_us`.
  virtual std::int64_t now_us() const = 0;
  // Makes a blocked or future read() return promptly (kEnd) so the reader thread can stop.
  // Called from another thread.
  virtual void interrupt() = 0;
};

} // namespace penshape::drivers
