#include "hid_recording_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "penshape/drivers/pen_descriptor_writer.hpp"
#include "penshape/drivers/recording.hpp"

namespace penshape::cli {
namespace {

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint32_t clamp_unsigned(std::int64_t v, std::int64_t max) {
  return static_cast<std::uint32_t>(std::clamp<std::int64_t>(v, 0, std::max<std::int64_t>(max, 0)));
}

std::uint8_t tilt_byte(std::int16_t degrees) {
  const auto t = static_cast<std::int8_t>(std::clamp<int>(degrees, -127, 127));
  return static_cast<std::uint8_t>(t);
}

} // namespace

std::vector<std::uint8_t> synthetic_pen_descriptor(const TabletInfo& tablet) {
  // The layout encode_pen_report writes (hid_recording_writer.hpp), by the drivers' writer.
  drivers::PenDescriptorSpec spec;
  spec.name = "penshape recorded pen";
  spec.report_id = kRecordedReportId;
  spec.x_max = std::max(tablet.x_max, 0);
  spec.y_max = std::max(tablet.y_max, 0);
  if (tablet.x_resolution > 0 && tablet.y_resolution > 0) {
    spec.width_mm = tablet.width_mm();
    spec.height_mm = tablet.height_mm();
  }
  spec.coordinate_bits = 32;
  spec.pressure_max = static_cast<std::int32_t>(
      std::min<std::uint32_t>(tablet.pressure_max, std::numeric_limits<std::int32_t>::max()));
  spec.pressure_bits = 32;
  spec.tilt = true;
  spec.tilt_degrees = 127;
  spec.eraser = true;
  spec.fine_units = true;
  return drivers::pen_descriptor(spec);
}

std::vector<std::uint8_t> encode_pen_report(const PenSample& s, const TabletInfo& tablet) {
  std::vector<std::uint8_t> out;
  out.reserve(kRecordedReportBytes);
  out.push_back(kRecordedReportId);
  std::uint8_t bits = 0;
  if (s.tip) bits |= 1U << 0;
  if ((s.buttons & kBarrel1) != 0) bits |= 1U << 1;
  if ((s.buttons & kBarrel2) != 0) bits |= 1U << 2;
  if ((s.buttons & kEraser) != 0) bits |= 1U << 3;
  if (s.in_range) bits |= 1U << 4;
  out.push_back(bits);
  put32(out, clamp_unsigned(s.x, tablet.x_max));
  put32(out, clamp_unsigned(s.y, tablet.y_max));
  put32(out, clamp_unsigned(s.pressure, tablet.pressure_max));
  out.push_back(tilt_byte(s.tilt_x));
  out.push_back(tilt_byte(s.tilt_y));
  return out;
}

HidRecordingWriter::HidRecordingWriter(std::ostream& out, const TabletInfo& tablet,
                                       const std::string& phys, const std::string& comment)
    : out_(out), tablet_(tablet) {
  out_ << "# " << drivers::single_line(comment) << "\n";
  out_ << "# penshape record: decoded samples re-encoded with a synthetic HID pen descriptor\n";
  drivers::Recording header;
  header.descriptor = synthetic_pen_descriptor(tablet);
  header.identity.name = tablet.name.empty() ? "penshape recorded pen" : tablet.name;
  header.identity.bus = tablet.bus;
  header.identity.vendor_id = tablet.vendor_id;
  header.identity.product_id = tablet.product_id;
  header.has_identity = true;
  header.phys = phys;
  out_ << drivers::hid_recorder_header(header);
}

void HidRecordingWriter::write(const PenSample& sample) {
  if (!have_epoch_) {
    have_epoch_ = true;
    epoch_us_ = sample.time_us;
  }
  drivers::HidEvent event;
  event.time_us = std::max<std::int64_t>(sample.time_us - epoch_us_, 0);
  event.bytes = encode_pen_report(sample, tablet_);
  out_ << drivers::hid_recorder_event_line(event);
  ++reports_;
}

} // namespace penshape::cli
