#pragma once
// Writes HID report descriptors: short items (HID 1.11, 6.2.2.2: a prefix byte with tag, type
// and size code, then 0, 1, 2 or 4 little-endian data bytes), and with them a standard
// Digitizer/Pen application as the HID Usage Tables describe it. The one descriptor writer: the
// CLI's re-encoded recordings (a tablet's decoded samples as a synthetic pen) and the tests'
// generated tablets (tests/support/gen) both use it.
#include <cstdint>
#include <string>
#include <vector>

namespace penshape::drivers {

// Item prefixes without their size bits.
namespace hid_item {
inline constexpr std::uint8_t kUsagePage = 0x04, kUsage = 0x08, kCollection = 0xA0,
                              kEndCollection = 0xC0, kInput = 0x80, kLogicalMin = 0x14,
                              kLogicalMax = 0x24, kPhysicalMin = 0x34, kPhysicalMax = 0x44,
                              kUnitExponent = 0x54, kUnit = 0x64, kReportSize = 0x74,
                              kReportId = 0x84, kReportCount = 0x94;
inline constexpr std::int64_t kDataVarAbs = 0x02, kConstant = 0x03;
} // namespace hid_item

class HidItemWriter {
 public:
  // An item with the smallest data size that holds `value` (signed when `is_signed`).
  void item(std::uint8_t prefix, std::int64_t value, bool is_signed = false);
  // Report Size, Report Count, then an Input item with `flags`.
  void input(std::int64_t size, std::int64_t count, std::int64_t flags);
  void end_collection() { bytes_.push_back(hid_item::kEndCollection); }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

// A pen: switches (tip, optional barrel and secondary barrel, invert or eraser, in range) padded
// to a byte, X and Y, tip pressure padded to a byte, optional X/Y tilt (8 bits each).
struct PenDescriptorSpec {
  std::string name;           // for messages and file names
  std::uint8_t report_id = 0; // 0: no report ID byte
  std::int32_t x_max = 0;     // logical maxima (minima are 0)
  std::int32_t y_max = 0;
  double width_mm = 0.0; // the active area; 0: no physical units
  double height_mm = 0.0;
  std::uint32_t coordinate_bits = 16;
  std::int32_t pressure_max = 0;
  std::uint32_t pressure_bits = 16;
  bool tilt = false;          // X/Y tilt in degrees, ±tilt_degrees, 8 bits each
  bool inches = false;        // physical size in 0.001 inch (else centimetres)
  bool barrel_buttons = true; // barrel switch and secondary barrel switch
  std::int32_t tilt_degrees = 60;
  bool eraser = false;     // the fourth switch is Eraser (else Invert)
  bool fine_units = false; // centimetres in 10^-3 (0.01 mm) steps, else 10^-2 (0.1 mm)
};

std::vector<std::uint8_t> pen_descriptor(const PenDescriptorSpec& spec);

} // namespace penshape::drivers
