// HID descriptor items and standard pen descriptors (pen_descriptor_writer.hpp).
#include "penshape/drivers/pen_descriptor_writer.hpp"

#include <algorithm>
#include <cmath>

namespace penshape::drivers {

using namespace hid_item;

void HidItemWriter::item(std::uint8_t prefix, std::int64_t value, bool is_signed) {
  int size = 4;
  if (is_signed ? (value >= -128 && value <= 127) : (value >= 0 && value <= 0xFF)) {
    size = 1;
  } else if (is_signed ? (value >= -32768 && value <= 32767) : (value >= 0 && value <= 0xFFFF)) {
    size = 2;
  }
  bytes_.push_back(static_cast<std::uint8_t>(prefix | (size == 4 ? 3 : size)));
  const auto raw = static_cast<std::uint64_t>(value);
  for (int i = 0; i < size; ++i) {
    bytes_.push_back(static_cast<std::uint8_t>((raw >> (8 * i)) & 0xFFU));
  }
}

void HidItemWriter::input(std::int64_t size, std::int64_t count, std::int64_t flags) {
  item(kReportSize, size);
  item(kReportCount, count);
  item(kInput, flags);
}

namespace {

bool physical(const PenDescriptorSpec& s) { return s.width_mm > 0 && s.height_mm > 0; }

// Millimetres in the spec's physical steps, within a 32-bit item.
std::int64_t physical_extent(const PenDescriptorSpec& s, double mm) {
  if (!physical(s)) return 0;
  const double steps = s.inches ? mm / 25.4 * 1000.0 : mm * (s.fine_units ? 100.0 : 10.0);
  return std::llround(std::clamp(steps, 0.0, 2147483647.0));
}

// X or Y: logical 0..max over the physical size.
void axis(HidItemWriter& w, const PenDescriptorSpec& s, std::uint8_t usage, std::int32_t max,
          double mm) {
  w.item(kUsage, usage);
  w.item(kLogicalMin, 0);
  w.item(kLogicalMax, max, true);
  w.item(kPhysicalMin, 0);
  w.item(kPhysicalMax, physical_extent(s, mm), true);
  w.input(s.coordinate_bits, 1, kDataVarAbs);
}

void switches(HidItemWriter& w, const PenDescriptorSpec& s) {
  const int count = s.barrel_buttons ? 5 : 3;
  w.item(kUsage, 0x42); // Tip Switch
  if (s.barrel_buttons) {
    w.item(kUsage, 0x44); // Barrel Switch
    w.item(kUsage, 0x5A); // Secondary Barrel Switch
  }
  w.item(kUsage, s.eraser ? 0x45 : 0x3C); // Eraser or Invert
  w.item(kUsage, 0x32);                   // In Range
  w.item(kLogicalMin, 0);
  w.item(kLogicalMax, 1);
  w.input(1, count, kDataVarAbs);
  w.input(1, 8 - count, kConstant);
}

void tilt(HidItemWriter& w, const PenDescriptorSpec& s) {
  w.item(kUsage, 0x3D); // X Tilt
  w.item(kUsage, 0x3E); // Y Tilt
  w.item(kLogicalMin, -s.tilt_degrees, true);
  w.item(kLogicalMax, s.tilt_degrees, true);
  w.item(kUnit, 0x14); // English rotation: degrees
  w.item(kPhysicalMin, -s.tilt_degrees, true);
  w.item(kPhysicalMax, s.tilt_degrees, true);
  w.input(8, 2, kDataVarAbs);
}

} // namespace

std::vector<std::uint8_t> pen_descriptor(const PenDescriptorSpec& s) {
  HidItemWriter w;
  w.item(kUsagePage, 0x0D);  // Digitizers
  w.item(kUsage, 0x02);      // Pen
  w.item(kCollection, 0x01); // Application
  if (s.report_id != 0) w.item(kReportId, s.report_id);
  w.item(kUsage, 0x20);      // Stylus
  w.item(kCollection, 0x00); // Physical
  switches(w, s);
  w.item(kUsagePage, 0x01); // Generic Desktop
  // English or SI linear length; 10^-3 inch, or 10^-2 / 10^-3 cm (4-bit two's complement).
  w.item(kUnit, !physical(s) ? 0x00 : s.inches ? 0x13 : 0x11);
  w.item(kUnitExponent, !physical(s) ? 0x00 : (s.inches || s.fine_units) ? 0x0D : 0x0E);
  axis(w, s, 0x30, s.x_max, s.width_mm);
  axis(w, s, 0x31, s.y_max, s.height_mm);
  w.item(kUnit, 0);
  w.item(kUnitExponent, 0);
  w.item(kPhysicalMax, 0);
  w.item(kUsagePage, 0x0D);
  w.item(kUsage, 0x30); // Tip Pressure
  w.item(kLogicalMax, s.pressure_max, true);
  w.input(s.pressure_bits, 1, kDataVarAbs);
  if (s.pressure_bits % 8 != 0) w.input(8 - s.pressure_bits % 8, 1, kConstant);
  if (s.tilt) tilt(w, s);
  w.end_collection();
  w.end_collection();
  return w.take();
}

} // namespace penshape::drivers
