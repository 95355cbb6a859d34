#include "hid_recording_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace penshape::cli {
namespace {

// Short items of the HID report descriptor: prefix (tag | type | size) then 0, 1, 2 or 4 bytes.
class Items {
 public:
  void item(std::uint8_t prefix) { bytes.push_back(prefix); }
  void item1(std::uint8_t prefix, std::uint8_t v) {
    bytes.push_back(static_cast<std::uint8_t>(prefix | 1U));
    bytes.push_back(v);
  }
  void item4(std::uint8_t prefix, std::uint32_t v) {
    bytes.push_back(static_cast<std::uint8_t>(prefix | 3U));
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  std::vector<std::uint8_t> bytes;
};

// Item prefixes without their size bits.
constexpr std::uint8_t kUsagePage = 0x04, kUsage = 0x08, kCollection = 0xA0, kEndCollection = 0xC0,
                       kInput = 0x80, kLogicalMin = 0x14, kLogicalMax = 0x24, kPhysicalMin = 0x34,
                       kPhysicalMax = 0x44, kUnitExponent = 0x54, kUnit = 0x64, kReportSize = 0x74,
                       kReportId = 0x84, kReportCount = 0x94;

std::uint32_t physical_extent(std::int32_t max, double resolution) {
  if (!(resolution > 0) || max <= 0) return 0;
  const double hundredths_mm = std::round(static_cast<double>(max) / resolution * 100.0);
  return static_cast<std::uint32_t>(std::clamp(hundredths_mm, 0.0, 4.0e9));
}

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
  Items d;
  d.item1(kUsagePage, 0x0D);  // Digitizer
  d.item1(kUsage, 0x02);      // Pen
  d.item1(kCollection, 0x01); // Application
  d.item1(kReportId, kRecordedReportId);
  d.item1(kUsage, 0x20);      // Stylus
  d.item1(kCollection, 0x00); // Physical
  d.item1(kUsage, 0x42);      // Tip Switch
  d.item1(kUsage, 0x44);      // Barrel Switch
  d.item1(kUsage, 0x5A);      // Secondary Barrel Switch
  d.item1(kUsage, 0x45);      // Eraser
  d.item1(kUsage, 0x32);      // In Range
  d.item1(kLogicalMin, 0);
  d.item1(kLogicalMax, 1);
  d.item1(kReportSize, 1);
  d.item1(kReportCount, 5);
  d.item1(kInput, 0x02); // Data, Variable, Absolute
  d.item1(kReportCount, 3);
  d.item1(kInput, 0x03);     // Constant padding
  d.item1(kUsagePage, 0x01); // Generic Desktop
  const bool physical = tablet.x_resolution > 0 && tablet.y_resolution > 0;
  d.item1(kUnit, physical ? 0x11 : 0x00);         // SI linear, centimetre
  d.item1(kUnitExponent, physical ? 0x0D : 0x00); // 10^-3 (4-bit two's complement)
  d.item1(kReportSize, 32);
  d.item1(kReportCount, 1);
  d.item1(kPhysicalMin, 0);
  d.item1(kUsage, 0x30); // X
  d.item4(kLogicalMax, static_cast<std::uint32_t>(std::max(tablet.x_max, 0)));
  d.item4(kPhysicalMax, physical_extent(tablet.x_max, tablet.x_resolution));
  d.item1(kInput, 0x02);
  d.item1(kUsage, 0x31); // Y
  d.item4(kLogicalMax, static_cast<std::uint32_t>(std::max(tablet.y_max, 0)));
  d.item4(kPhysicalMax, physical_extent(tablet.y_max, tablet.y_resolution));
  d.item1(kInput, 0x02);
  d.item1(kUsagePage, 0x0D); // Digitizer
  d.item1(kUnit, 0x00);
  d.item1(kUnitExponent, 0x00);
  d.item1(kPhysicalMax, 0);
  d.item1(kUsage, 0x30); // Tip Pressure
  d.item4(kLogicalMax, tablet.pressure_max);
  d.item1(kInput, 0x02);
  d.item1(kUsage, 0x3D);      // X Tilt
  d.item1(kUsage, 0x3E);      // Y Tilt
  d.item1(kLogicalMin, 0x81); // -127
  d.item1(kLogicalMax, 0x7F); // 127
  d.item1(kPhysicalMin, 0x81);
  d.item1(kPhysicalMax, 0x7F);
  d.item1(kUnit, 0x14); // English rotation, degrees
  d.item1(kReportSize, 8);
  d.item1(kReportCount, 2);
  d.item1(kInput, 0x02);
  d.item(kEndCollection);
  d.item(kEndCollection);
  return d.bytes;
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

namespace {

std::string hex_bytes(const std::vector<std::uint8_t>& bytes) {
  std::string out;
  char buf[4];
  for (const auto b : bytes) {
    std::snprintf(buf, sizeof buf, " %02x", b);
    out += buf;
  }
  return out;
}

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

} // namespace

HidRecordingWriter::HidRecordingWriter(std::ostream& out, const TabletInfo& tablet,
                                       const std::string& phys, const std::string& comment)
    : out_(out), tablet_(tablet) {
  out_ << "# " << one_line(comment) << "\n";
  out_ << "# penshape record: decoded samples re-encoded with a synthetic HID pen descriptor\n";
  const auto descriptor = synthetic_pen_descriptor(tablet);
  out_ << "D: 0\n";
  out_ << "R: " << descriptor.size() << hex_bytes(descriptor) << "\n";
  out_ << "N: " << one_line(tablet.name.empty() ? "penshape recorded pen" : tablet.name) << "\n";
  out_ << "P: " << one_line(phys) << "\n";
  char ids[32];
  std::snprintf(ids, sizeof ids, "I: %x %04x %04x", static_cast<unsigned>(tablet.bus),
                tablet.vendor_id, tablet.product_id);
  out_ << ids << "\nD: 0\n";
}

void HidRecordingWriter::write(const PenSample& sample) {
  if (!have_epoch_) {
    have_epoch_ = true;
    epoch_us_ = sample.time_us;
  }
  const std::int64_t t = std::max<std::int64_t>(sample.time_us - epoch_us_, 0);
  char stamp[48];
  std::snprintf(stamp, sizeof stamp, "E: %lld.%06lld %zu", static_cast<long long>(t / 1'000'000),
                static_cast<long long>(t % 1'000'000), kRecordedReportBytes);
  out_ << stamp << hex_bytes(encode_pen_report(sample, tablet_)) << "\n";
  ++reports_;
}

} // namespace penshape::cli
