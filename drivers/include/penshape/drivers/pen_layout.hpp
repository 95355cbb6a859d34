#pragma once
// Where the pen's values sit in a report: built from a parsed HID descriptor (generic HID pens)
// or by a vendor protocol (reports the descriptor does not describe). One decoder reads both.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "penshape/drivers/hid_descriptor.hpp"
#include "penshape/types/tablet_info.hpp"

namespace penshape::drivers {

// One value in a report. `bit_size == 0` means the report does not carry it. A value may be
// split in up to three pieces, least significant first: `bit_size` bits at `bit_offset`, then
// `high_bit_size` bits at `high_bit_offset`, then `top_bit_size` bits at `top_bit_offset`
// (UC-Logic keeps the third coordinate byte apart; Wacom Intuos scatters pressure over three
// bytes). `high_big_endian`: the high piece is whole bytes in big-endian order (Intuos X/Y).
struct PenField {
  std::uint32_t bit_offset = 0;
  std::uint32_t bit_size = 0;
  std::uint32_t high_bit_offset = 0;
  std::uint32_t high_bit_size = 0;
  std::uint32_t top_bit_offset = 0;
  std::uint32_t top_bit_size = 0;
  bool high_big_endian = false;
  bool is_signed = false;
  bool inverted = false; // a flag that reads 1 when the condition is false
  std::int32_t logical_minimum = 0;
  std::int32_t logical_maximum = 0;

  [[nodiscard]] bool present() const { return bit_size > 0; }
  [[nodiscard]] std::uint32_t total_bits() const { return bit_size + high_bit_size + top_bit_size; }
};

// The layout of one pen input report.
struct PenLayout {
  std::uint8_t report_id = 0; // 0: the device sends no report ID byte
  bool uses_report_id = false;
  // Vendor formats whose report ID differs between models (Veikk, Acepen): any ID that no other
  // layout claims; told apart by the match bytes. Only used when no descriptor pen exists.
  bool any_report_id = false;
  std::uint32_t min_report_bytes = 0; // shorter reports are junk (including the ID byte)
  // Vendor reports that share one report ID with non-pen reports: a report is the pen's only if
  // (report[match_byte] & match_mask) == match_value, or, with match_reject, only if it is not.
  // match_mask 0 accepts every report.
  std::uint32_t match_byte = 0;
  std::uint8_t match_mask = 0;
  std::uint8_t match_value = 0;
  bool match_reject = false;
  // A second condition of the same form, which must hold too (mask 0: none).
  std::uint32_t match2_byte = 0;
  std::uint8_t match2_mask = 0;
  std::uint8_t match2_value = 0;
  bool match2_reject = false;

  PenField tip, in_range, barrel1, barrel2, barrel3, eraser, invert;
  PenField x, y, pressure, tilt_x, tilt_y;
  // Tilt in degrees = (logical - logical_minimum) * tilt_scale + tilt_offset.
  double tilt_scale = 1.0;
  double tilt_offset = 0.0;

  // Without a tip field: tip = pressure > tip_pressure_threshold (Wacom Intuos uses 10).
  std::uint32_t tip_pressure_threshold = 0;

  double x_resolution = 0.0; // units per mm, 0 when the descriptor gives no physical size
  double y_resolution = 0.0;
  std::string origin; // "hid" or the vendor protocol that built it

  [[nodiscard]] std::int32_t x_max() const { return x.logical_maximum - x.logical_minimum; }
  [[nodiscard]] std::int32_t y_max() const { return y.logical_maximum - y.logical_minimum; }
  [[nodiscard]] std::uint32_t pressure_max() const {
    return pressure.present()
               ? static_cast<std::uint32_t>(pressure.logical_maximum - pressure.logical_minimum)
               : 0U;
  }
};

// A layout's pen fields with their names, in the order `penshape hid describe` lists them.
struct NamedPenField {
  const char* name;
  PenField PenLayout::*field;
};
inline constexpr std::array<NamedPenField, 12> kNamedPenFields{{{"tip", &PenLayout::tip},
                                                                {"in_range", &PenLayout::in_range},
                                                                {"barrel1", &PenLayout::barrel1},
                                                                {"barrel2", &PenLayout::barrel2},
                                                                {"barrel3", &PenLayout::barrel3},
                                                                {"eraser", &PenLayout::eraser},
                                                                {"invert", &PenLayout::invert},
                                                                {"x", &PenLayout::x},
                                                                {"y", &PenLayout::y},
                                                                {"pressure", &PenLayout::pressure},
                                                                {"tilt_x", &PenLayout::tilt_x},
                                                                {"tilt_y", &PenLayout::tilt_y}}};

// Every pen input report of a descriptor: a report with absolute X and Y plus a tip switch, tip
// pressure or in-range bit, inside a pen/digitizer application or a stylus collection, or a
// mouse-mode report that carries tip pressure (UC-Logic firmware mode). Touch (finger) reports
// are not pens. The digitizer-page reports come first.
std::vector<PenLayout> find_pen_layouts(const ParsedDescriptor& descriptor);

// Units per millimetre of an axis field from its physical extents and unit, 0 when unknown.
double resolution_per_mm(const ReportField& axis);

// Fills maxima, resolution and tilt of `info` from a layout (identity fields are left alone).
void apply_layout(const PenLayout& layout, TabletInfo& info);

} // namespace penshape::drivers
