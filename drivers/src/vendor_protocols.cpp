#include "penshape/drivers/vendor_protocols.hpp"

#include <string>

namespace penshape::drivers {
namespace {

PenField bit_flag(std::uint32_t byte, std::uint32_t bit, bool inverted = false) {
  PenField f;
  f.bit_offset = byte * 8 + bit;
  f.bit_size = 1;
  f.inverted = inverted;
  f.logical_maximum = 1;
  return f;
}

PenField value(std::uint32_t bit_offset, std::uint32_t bits, std::int32_t lmin, std::int32_t lmax,
               bool is_signed = false) {
  PenField f;
  f.bit_offset = bit_offset;
  f.bit_size = bits;
  f.is_signed = is_signed;
  f.logical_minimum = lmin;
  f.logical_maximum = lmax;
  return f;
}

std::uint32_t le(std::span<const std::uint8_t> b, std::size_t at, std::size_t n) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < n; ++i) v |= static_cast<std::uint32_t>(b[at + i]) << (8 * i);
  return v;
}

} // namespace

UcLogicParams parse_uclogic_params(std::span<const std::uint8_t> s, int version) {
  if (version != 1 && version != 2) throw std::invalid_argument("UC-Logic params: bad version");
  // v1 (string 100): X le16 @2, Y le16 @4, pressure le16 @8, resolution le16 @10.
  // v2 (string 200): X le24 @2, Y le24 @5, pressure le16 @8, resolution le16 @10.
  if (s.size() < 12) {
    throw std::invalid_argument("UC-Logic params: string descriptor of " +
                                std::to_string(s.size()) + " bytes, need 12");
  }
  if (s[1] != 0x03) throw std::invalid_argument("UC-Logic params: not a string descriptor");
  if (s[0] < 12) throw std::invalid_argument("UC-Logic params: bLength below 12");
  UcLogicParams p;
  p.version = version;
  p.x_max = static_cast<std::int32_t>(version == 2 ? le(s, 2, 3) : le(s, 2, 2));
  p.y_max = static_cast<std::int32_t>(version == 2 ? le(s, 5, 3) : le(s, 4, 2));
  p.pressure_max = le(s, 8, 2);
  p.resolution_lpi = le(s, 10, 2);
  if (p.x_max <= 0 || p.y_max <= 0 || p.pressure_max == 0) {
    throw std::invalid_argument("UC-Logic params: zero maxima (tablet not in a known mode)");
  }
  return p;
}

PenLayout uclogic_pen_layout(const UcLogicParams& p) {
  PenLayout l;
  l.uses_report_id = true;
  l.tip = bit_flag(1, 0);
  l.barrel1 = bit_flag(1, 1);
  l.barrel2 = bit_flag(1, 2);
  l.pressure = value(48, 16, 0, static_cast<std::int32_t>(p.pressure_max));
  if (p.version == 2) {
    l.origin = "uclogic-v2";
    l.report_id = 0x08;
    l.min_report_bytes = 12;
    l.in_range = bit_flag(1, 7);
    l.match_byte = 1;
    l.match_mask = 0x60; // pen: 0x00/0x8N; pad frames: 0xE0 buttons, 0xF0/0xF1 dials and strips
    l.match_value = 0x00;
    l.x = value(16, 16, 0, p.x_max);
    l.x.high_bit_offset = 64;
    l.x.high_bit_size = 8;
    l.y = value(32, 16, 0, p.y_max);
    l.y.high_bit_offset = 72;
    l.y.high_bit_size = 8;
    l.tilt_x = value(80, 8, -127, 127, true);
    l.tilt_y = value(88, 8, -127, 127, true);
    l.tilt_offset = -127.0;
  } else {
    l.origin = "uclogic-v1";
    l.report_id = 0x07;
    l.min_report_bytes = 8;
    l.in_range = bit_flag(1, 6, /*inverted=*/true);
    l.match_byte = 1;
    l.match_mask = 0xE0; // pad frames are 0xE0; pens 0x80..0xC7 never have all three bits
    l.match_value = 0xE0;
    l.match_reject = true;
    l.x = value(16, 16, 0, p.x_max);
    l.y = value(32, 16, 0, p.y_max);
  }
  const double per_mm = p.resolution_lpi / 25.4;
  l.x_resolution = per_mm;
  l.y_resolution = per_mm;
  return l;
}

PenLayout wacom_graphire_pen_layout(const TabletSpec& spec) {
  PenLayout l;
  l.origin = "wacom-graphire";
  l.report_id = 0x02;
  l.uses_report_id = true;
  l.min_report_bytes = 8;
  l.in_range = bit_flag(1, 7);
  l.eraser = bit_flag(1, 5);
  l.tip = bit_flag(1, 0);
  l.barrel1 = bit_flag(1, 1);
  l.barrel2 = bit_flag(1, 2);
  l.match_byte = 1;
  l.match_mask = 0x40; // tool 2 (bit 6) is the Graphire mouse
  l.match_value = 0x00;
  l.x = value(16, 16, 0, spec.x_max);
  l.y = value(32, 16, 0, spec.y_max);
  l.pressure = value(48, 8, 0, static_cast<std::int32_t>(spec.pressure_max));
  l.pressure.high_bit_offset = 56;
  l.pressure.high_bit_size = 2;
  l.x_resolution = spec.x_resolution;
  l.y_resolution = spec.y_resolution;
  return l;
}

PenLayout wacom_bamboo_pen_layout(const TabletSpec& spec) {
  PenLayout l;
  l.origin = "wacom-bamboo";
  l.report_id = 0x02;
  l.uses_report_id = true;
  l.min_report_bytes = 9;
  l.in_range = bit_flag(1, 6);
  l.tip = bit_flag(1, 0);
  l.barrel1 = bit_flag(1, 1);
  l.barrel2 = bit_flag(1, 2);
  l.eraser = bit_flag(1, 3);
  l.x = value(16, 16, 0, spec.x_max);
  l.y = value(32, 16, 0, spec.y_max);
  l.pressure = value(48, 16, 0, static_cast<std::int32_t>(spec.pressure_max));
  l.x_resolution = spec.x_resolution;
  l.y_resolution = spec.y_resolution;
  return l;
}

std::vector<PenLayout> wacom_intuos_pen_layouts(const TabletSpec& spec) {
  PenLayout l;
  l.origin = "wacom-intuos";
  l.report_id = 0x02;
  l.uses_report_id = true;
  l.min_report_bytes = 10;
  l.match_byte = 1;
  l.match_mask = 0xB8;
  l.match_value = 0xA0;
  // X: bit 1 of byte 9 below the big-endian word at byte 2 (17 bits in all).
  l.x = value(9 * 8 + 1, 1, 0, spec.x_max);
  l.x.high_bit_offset = 16;
  l.x.high_bit_size = 16;
  l.x.high_big_endian = true;
  l.y = value(9 * 8, 1, 0, spec.y_max);
  l.y.high_bit_offset = 32;
  l.y.high_bit_size = 16;
  l.y.high_big_endian = true;
  // Pressure: byte 1 bit 0, byte 7 bits 6-7, byte 6.
  l.pressure = value(8, 1, 0, static_cast<std::int32_t>(spec.pressure_max));
  l.pressure.high_bit_offset = 7 * 8 + 6;
  l.pressure.high_bit_size = 2;
  l.pressure.top_bit_offset = 6 * 8;
  l.pressure.top_bit_size = 8;
  l.tilt_x = value(8 * 8 + 7, 1, 0, 127);
  l.tilt_x.high_bit_offset = 7 * 8;
  l.tilt_x.high_bit_size = 6;
  l.tilt_y = value(8 * 8, 7, 0, 127);
  l.tilt_offset = -64.0;
  l.barrel1 = bit_flag(1, 1);
  l.barrel2 = bit_flag(1, 2);
  l.tip_pressure_threshold = 10;
  l.x_resolution = spec.x_resolution;
  l.y_resolution = spec.y_resolution;

  PenLayout out = l; // leaving proximity: same place, in range false (bit 6 is clear there)
  out.origin = "wacom-intuos (out of proximity)";
  out.match_mask = 0xFE;
  out.match_value = 0x80;
  out.in_range = bit_flag(1, 6);
  return {l, out};
}

PenLayout xppen_pen_layout(const TabletSpec& spec) {
  PenLayout l;
  l.origin = "xppen";
  l.report_id = 0x02;
  l.uses_report_id = true;
  l.min_report_bytes = 10;
  l.in_range = bit_flag(1, 6, /*inverted=*/true);
  l.tip = bit_flag(1, 0);
  l.barrel1 = bit_flag(1, 1);
  l.barrel2 = bit_flag(1, 2);
  l.match_byte = 1;
  l.match_mask = 0xF0;
  l.match_value = 0xF0;
  l.match_reject = true;
  l.x = value(16, 16, 0, spec.x_max);
  l.y = value(32, 16, 0, spec.y_max);
  l.pressure = value(48, 16, 0, static_cast<std::int32_t>(spec.pressure_max));
  l.tilt_x = value(64, 8, -127, 127, true);
  l.tilt_y = value(72, 8, -127, 127, true);
  l.tilt_offset = -127.0;
  l.x_resolution = spec.x_resolution;
  l.y_resolution = spec.y_resolution;
  return l;
}

} // namespace penshape::drivers
