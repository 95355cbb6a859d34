#pragma once
// Writes pen samples as a hid-recorder text file (the format of the hid-tools project: `R:`
// report descriptor, `N:` name, `P:` physical path, `I:` bus vid pid, `E: sec.usec len bytes`),
// for `penshape record --decoded` (a daemon without raw reports; record_command_capture.hpp
// writes the device's own bytes).
//
// Such a daemon delivers decoded samples, not the tablet's raw reports, so the file carries a
// synthetic descriptor: a standard HID digitizer pen (usage page 0x0D) whose logical ranges are
// the tablet's and whose physical ranges encode its resolution. Any HID parser (ours, the
// kernel's, hid-tools') decodes it back to the same samples.
//
// Report layout (16 bytes, little endian), report ID 2:
//   byte 0      report ID (2)
//   byte 1      bit 0 tip switch, 1 barrel switch, 2 secondary barrel switch, 3 eraser,
//               4 in range, bits 5-7 padding
//   bytes 2-5   X, unsigned 32-bit, 0..x_max (physical: x_max / x_resolution mm)
//   bytes 6-9   Y, unsigned 32-bit, 0..y_max
//   bytes 10-13 tip pressure, unsigned 32-bit, 0..pressure_max
//   byte 14     X tilt, signed 8-bit degrees (-127..127)
//   byte 15     Y tilt, signed 8-bit degrees
// Not representable: the third barrel button (dropped); tilt beyond ±127° (clamped).
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "penshape/types/pen_sample.hpp"
#include "penshape/types/tablet_info.hpp"

namespace penshape::cli {

inline constexpr std::uint8_t kRecordedReportId = 2;
inline constexpr std::size_t kRecordedReportBytes = 16;

// The descriptor for `tablet`. Physical extents are in units of 10^-3 cm (0.01 mm), rounded; a
// tablet with unknown resolution gets no physical units.
std::vector<std::uint8_t> synthetic_pen_descriptor(const TabletInfo& tablet);

// One report for `sample`; coordinates outside 0..max are clamped into the logical range.
std::vector<std::uint8_t> encode_pen_report(const PenSample& sample, const TabletInfo& tablet);

class HidRecordingWriter {
 public:
  // Writes the header: comments naming where the data came from, then R:, N:, P:, I:.
  HidRecordingWriter(std::ostream& out, const TabletInfo& tablet, const std::string& phys,
                     const std::string& comment);
  // One E: line; times are relative to the first sample written.
  void write(const PenSample& sample);
  [[nodiscard]] std::size_t reports() const { return reports_; }

 private:
  std::ostream& out_;
  TabletInfo tablet_;
  bool have_epoch_ = false;
  std::int64_t epoch_us_ = 0;
  std::size_t reports_ = 0;
};

} // namespace penshape::cli
