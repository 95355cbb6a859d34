#pragma once
// The capture `penshape record` writes: a hid-recorder file made of the device's own report
// descriptor, name, ids and raw reports as penshaped forwards them (DeviceInfo.hid and RawReport
// events), so the file replays here (`penshape replay --local`, `penshaped --replay`) and in
// hid-tools (hid-replay) exactly like the device.
//
// Layout, as hid-recorder writes it: `#` comment lines saying where it came from, `D: 0`, R:, N:,
// P:, I: (left out when bus and ids are unknown), the vendor strings as `# penshape-string:`
// comments (recording.hpp), `D: 0`, then one `E: sec.usec len bytes` line per report. Times are
// relative to the first report written, as hid-recorder's are, and never decrease (a clock that
// steps back repeats the previous time).
#include <cstdint>
#include <deque>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>

#include "penshape/drivers/recording.hpp"
#include "penshape/v1/live.pb.h"

namespace penshape::cli {

// The hid-recorder header facts of a device as penshaped describes it; nullopt when the daemon
// sent none (it predates raw reports, or the device has no HID descriptor). Throws
// std::invalid_argument naming the field for facts no file can hold (a vendor string index above
// 255, an id above 0xffff, a report descriptor beyond the kernel's 4,096-byte limit).
std::optional<drivers::Recording> capture_header(const v1::DeviceInfo& device);

class CaptureWriter {
 public:
  // Writes the header: `comment` (one line per '\n'-separated part), then the facts.
  // `track_ends`: remember where each report's line ends, for cut_after().
  CaptureWriter(std::ostream& out, const drivers::Recording& header, const std::string& comment,
                bool track_ends);

  // One E: line for a report read at `time_us` (the device's clock).
  void write(std::string_view report, std::int64_t time_us);
  [[nodiscard]] std::size_t reports() const { return reports_; }
  [[nodiscard]] std::uint64_t bytes_written() const { return bytes_; }

  // With track_ends: the file size (and report count) that keeps exactly the reports read at or
  // before `time_us` (device clock) among those still remembered; the header alone when none is.
  struct Cut {
    std::uint64_t bytes = 0;
    std::size_t reports = 0;
  };
  [[nodiscard]] Cut cut_through(std::int64_t time_us) const;
  // Forgets report ends before `time_us` except the last of them (bounds the memory while
  // tracking: only times after the last finished stroke are ever asked for).
  void forget_before(std::int64_t time_us);

 private:
  void put(const std::string& text);

  std::ostream& out_;
  bool track_ends_;
  std::uint64_t bytes_ = 0;
  std::uint64_t header_bytes_ = 0;
  std::size_t reports_ = 0;
  std::optional<std::int64_t> first_time_us_;
  std::int64_t last_relative_us_ = 0;
  std::deque<std::pair<std::int64_t, Cut>> ends_; // device time -> the file just after it
};

} // namespace penshape::cli
