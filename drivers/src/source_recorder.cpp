#include "penshape/drivers/live_recorder.hpp"

namespace penshape::drivers {

std::size_t record_source(ReportSource& source, const Recording& header, std::ostream& out,
                          const std::atomic<bool>& stop, std::chrono::milliseconds max_duration) {
  out << hid_recorder_header(header) << std::flush;
  const auto deadline = std::chrono::steady_clock::now() + max_duration;
  std::size_t written = 0;
  std::vector<std::uint8_t> bytes;
  while (!stop && std::chrono::steady_clock::now() < deadline) {
    std::int64_t t = 0;
    const ReadStatus st = source.read(bytes, t, std::chrono::milliseconds(100));
    if (st == ReadStatus::kReport) {
      out << hid_recorder_event_line({t, bytes}) << std::flush;
      ++written;
    } else if (st != ReadStatus::kTimeout) {
      break;
    }
  }
  return written;
}

} // namespace penshape::drivers
