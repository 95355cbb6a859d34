// Writes standard HID pen descriptors (see descriptor_gen.hpp). Items are short items: a prefix
// byte (tag, type, size code) then 0, 1, 2 or 4 little-endian data bytes (HID 1.11, 6.2.2.2).
#include "descriptor_gen.hpp"

#include <cmath>

namespace penshape::gen {
namespace {

class Writer {
 public:
  // An item with the smallest size that holds `value` (signed when `is_signed`).
  void item(std::uint8_t prefix, std::int64_t value, bool is_signed = false) {
    int size = 4;
    if (is_signed ? (value >= -128 && value <= 127) : (value >= 0 && value <= 0xFF))
      size = 1;
    else if (is_signed ? (value >= -32768 && value <= 32767) : (value >= 0 && value <= 0xFFFF))
      size = 2;
    bytes_.push_back(static_cast<std::uint8_t>(prefix | (size == 4 ? 3 : size)));
    const auto raw = static_cast<std::uint64_t>(value);
    for (int i = 0; i < size; ++i)
      bytes_.push_back(static_cast<std::uint8_t>((raw >> (8 * i)) & 0xFFU));
  }
  void raw(std::uint8_t byte) { bytes_.push_back(byte); }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

// Prefixes without their size bits.
constexpr std::uint8_t kUsagePage = 0x04, kUsage = 0x08, kCollection = 0xA0, kEndCollection = 0xC0;
constexpr std::uint8_t kLogicalMin = 0x14, kLogicalMax = 0x24, kPhysicalMin = 0x34,
                       kPhysicalMax = 0x44;
constexpr std::uint8_t kUnitExponent = 0x54, kUnit = 0x64, kReportSize = 0x74, kReportId = 0x84;
constexpr std::uint8_t kReportCount = 0x94, kInput = 0x80;
constexpr std::int64_t kDataVarAbs = 0x02, kConstant = 0x03;

void input(Writer& w, std::int64_t size, std::int64_t count, std::int64_t flags) {
  w.item(kReportSize, size);
  w.item(kReportCount, count);
  w.item(kInput, flags);
}

// X or Y: logical 0..max over the physical size, in 0.01 cm or 0.001 inch.
void axis(Writer& w, const PenDescriptorSpec& s, std::uint8_t usage, std::int32_t max, double mm) {
  w.item(kUsage, usage);
  w.item(kLogicalMin, 0);
  w.item(kLogicalMax, max, true);
  w.item(kPhysicalMin, 0);
  w.item(kPhysicalMax, std::llround(s.inches ? mm / 25.4 * 1000.0 : mm * 10.0), true);
  input(w, s.coordinate_bits, 1, kDataVarAbs);
}

} // namespace

std::vector<std::uint8_t> pen_descriptor(const PenDescriptorSpec& s) {
  Writer w;
  w.item(kUsagePage, 0x0D);  // Digitizers
  w.item(kUsage, 0x02);      // Pen
  w.item(kCollection, 0x01); // Application
  if (s.report_id != 0) w.item(kReportId, s.report_id);
  w.item(kUsage, 0x20);      // Stylus
  w.item(kCollection, 0x00); // Physical
  const int switches = s.barrel_buttons ? 5 : 3;
  w.item(kUsage, 0x42); // Tip Switch
  if (s.barrel_buttons) {
    w.item(kUsage, 0x44); // Barrel Switch
    w.item(kUsage, 0x5A); // Secondary Barrel Switch
  }
  w.item(kUsage, 0x3C); // Invert
  w.item(kUsage, 0x32); // In Range
  w.item(kLogicalMin, 0);
  w.item(kLogicalMax, 1);
  input(w, 1, switches, kDataVarAbs);
  input(w, 1, 8 - switches, kConstant);
  w.item(kUsagePage, 0x01);                      // Generic Desktop
  w.item(kUnit, s.inches ? 0x13 : 0x11);         // English or SI linear, length
  w.item(kUnitExponent, s.inches ? 0x0D : 0x0E); // 10^-3 inch or 10^-2 cm (4-bit two's complement)
  axis(w, s, 0x30, s.x_max, s.width_mm);
  axis(w, s, 0x31, s.y_max, s.height_mm);
  w.item(kUnit, 0);
  w.item(kUnitExponent, 0);
  w.item(kPhysicalMax, 0);
  w.item(kUsagePage, 0x0D);
  w.item(kUsage, 0x30); // Tip Pressure
  w.item(kLogicalMax, s.pressure_max, true);
  input(w, s.pressure_bits, 1, kDataVarAbs);
  if (s.pressure_bits % 8 != 0) input(w, 8 - s.pressure_bits % 8, 1, kConstant);
  if (s.tilt) {
    w.item(kUsage, 0x3D); // X Tilt
    w.item(kUsage, 0x3E); // Y Tilt
    w.item(kLogicalMin, -60, true);
    w.item(kLogicalMax, 60, true);
    w.item(kUnit, 0x14); // English rotation: degrees
    w.item(kPhysicalMin, -60, true);
    w.item(kPhysicalMax, 60, true);
    input(w, 8, 2, kDataVarAbs);
  }
  w.raw(kEndCollection);
  w.raw(kEndCollection);
  return w.take();
}

std::vector<std::uint8_t> vendor_pen_descriptor(std::uint8_t report_id, int report_bytes) {
  Writer w;
  w.item(kUsagePage, 0x0D);  // Digitizers
  w.item(kUsage, 0x01);      // Digitizer
  w.item(kCollection, 0x01); // Application
  w.item(kReportId, report_id);
  w.item(kCollection, 0x00);  // Physical
  w.item(kUsagePage, 0xFF00); // vendor-defined
  w.item(kUsage, 0x01);
  w.item(kLogicalMin, 0);
  w.item(kLogicalMax, 0xFF);
  input(w, 8, report_bytes - 1, kDataVarAbs);
  w.raw(kEndCollection);
  w.raw(kEndCollection);
  return w.take();
}

const std::vector<PenDescriptorSpec>& pen_descriptor_specs() {
  static const std::vector<PenDescriptorSpec> specs{
      // name, report id, x max, y max, width, height, coordinate bits, pressure max, bits, tilt,
      // inches
      {"small-8192-id7", 7, 32000, 20000, 160.0, 100.0, 16, 8191, 16, false, false, true},
      {"medium-tilt-id2", 2, 44800, 28000, 224.0, 140.0, 16, 8191, 16, true, false, true},
      {"large-24bit-inch", 8, 152400, 95250, 304.8, 190.5, 24, 16383, 16, true, true, true},
      {"basic-no-id-1024", 0, 15200, 9500, 152.0, 95.0, 16, 1023, 12, false, false, false},
      {"tiny-inch-255", 1, 5080, 3810, 50.8, 38.1, 16, 255, 8, false, true, true},
  };
  return specs;
}

} // namespace penshape::gen
