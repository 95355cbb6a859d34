#pragma once
// Recording a device to a hid-recorder file: the header first, then one `E:` line per report
// as it arrives (flushed, so a crash or unplug keeps what was recorded).
#include <atomic>
#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>

#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/report_source.hpp"

namespace penshape::drivers {

// Writes `header` (N:/P:/I:/R: and penshape-string lines; its events are ignored), then the
// reports of `source` until it ends or vanishes, `stop` becomes true, or `max_duration` passes.
// Returns the number of reports written.
std::size_t record_source(ReportSource& source, const Recording& header, std::ostream& out,
                          const std::atomic<bool>& stop, std::chrono::milliseconds max_duration);

// Opens a live hidraw node (e.g. /dev/hidraw3): identity and descriptor from sysfs (or the
// HIDIOCGRDESC ioctl), the tablet's vendor strings and init reports, then record_source.
// Throws std::runtime_error when the node cannot be opened.
std::size_t record_hidraw(const std::string& path, std::ostream& out, const std::atomic<bool>& stop,
                          std::chrono::milliseconds max_duration);

} // namespace penshape::drivers
