#include "penshape/drivers/pen_encoder.hpp"

#include <algorithm>
#include <cmath>

namespace penshape::drivers {
namespace {

void insert_bits(std::vector<std::uint8_t>& r, std::uint32_t bit_offset, std::uint32_t bit_size,
                 std::uint32_t value) {
  for (std::uint32_t i = 0; i < bit_size; ++i) {
    const std::uint32_t bit = bit_offset + i;
    if (bit / 8 >= r.size()) return;
    const auto mask = static_cast<std::uint8_t>(1U << (bit % 8));
    if (((value >> i) & 1U) != 0) {
      r[bit / 8] = static_cast<std::uint8_t>(r[bit / 8] | mask);
    } else {
      r[bit / 8] = static_cast<std::uint8_t>(r[bit / 8] & ~mask);
    }
  }
}

// Writes a logical value into a (possibly split) field, the inverse of the decoder's read.
void write_value(std::vector<std::uint8_t>& r, const PenField& f, std::int64_t logical) {
  if (!f.present()) return;
  logical = std::clamp<std::int64_t>(logical, f.logical_minimum, f.logical_maximum);
  auto v = static_cast<std::uint32_t>(logical); // two's complement for signed fields
  insert_bits(r, f.bit_offset, f.bit_size, v);
  v = f.bit_size >= 32 ? 0 : v >> f.bit_size;
  if (f.high_bit_size > 0) {
    std::uint32_t high = v & ((f.high_bit_size >= 32) ? ~0U : ((1U << f.high_bit_size) - 1U));
    if (f.high_big_endian) {
      std::uint32_t swapped = 0;
      for (std::uint32_t i = 0; i < f.high_bit_size / 8; ++i) {
        swapped = (swapped << 8) | ((high >> (8 * i)) & 0xFFU);
      }
      high = swapped;
    }
    insert_bits(r, f.high_bit_offset, f.high_bit_size, high);
    v = f.high_bit_size >= 32 ? 0 : v >> f.high_bit_size;
  }
  if (f.top_bit_size > 0) insert_bits(r, f.top_bit_offset, f.top_bit_size, v);
}

void write_flag(std::vector<std::uint8_t>& r, const PenField& f, bool set) {
  if (f.present()) insert_bits(r, f.bit_offset, f.bit_size, (set != f.inverted) ? 1U : 0U);
}

std::int64_t tilt_logical(const PenLayout& l, const PenField& f, std::int16_t degrees) {
  const double scale = l.tilt_scale != 0 ? l.tilt_scale : 1.0;
  return std::llround((degrees - l.tilt_offset) / scale) + f.logical_minimum;
}

} // namespace

std::vector<std::uint8_t> encode_pen_report(const PenLayout& layout, const PenSample& sample) {
  std::vector<std::uint8_t> r(std::max<std::uint32_t>(layout.min_report_bytes, 1U), 0);
  if (layout.uses_report_id) r[0] = layout.report_id;
  if (layout.match_mask != 0 && !layout.match_reject && layout.match_byte < r.size()) {
    r[layout.match_byte] = static_cast<std::uint8_t>((r[layout.match_byte] & ~layout.match_mask) |
                                                     (layout.match_value & layout.match_mask));
  }
  if (layout.match2_mask != 0 && !layout.match2_reject && layout.match2_byte < r.size()) {
    r[layout.match2_byte] = static_cast<std::uint8_t>(
        (r[layout.match2_byte] & ~layout.match2_mask) | (layout.match2_value & layout.match2_mask));
  }
  write_value(r, layout.x, std::int64_t{sample.x} + layout.x.logical_minimum);
  write_value(r, layout.y, std::int64_t{sample.y} + layout.y.logical_minimum);
  write_value(r, layout.pressure, std::int64_t{sample.pressure} + layout.pressure.logical_minimum);
  if (layout.tilt_x.present()) {
    write_value(r, layout.tilt_x, tilt_logical(layout, layout.tilt_x, sample.tilt_x));
    write_value(r, layout.tilt_y, tilt_logical(layout, layout.tilt_y, sample.tilt_y));
  }
  write_flag(r, layout.tip, sample.tip);
  write_flag(r, layout.in_range, sample.in_range);
  write_flag(r, layout.barrel1, (sample.buttons & kBarrel1) != 0);
  write_flag(r, layout.barrel2, (sample.buttons & kBarrel2) != 0);
  write_flag(r, layout.barrel3, (sample.buttons & kBarrel3) != 0);
  const bool eraser = (sample.buttons & kEraser) != 0;
  write_flag(r, layout.eraser, eraser && layout.eraser.present());
  write_flag(r, layout.invert, eraser && !layout.eraser.present());
  return r;
}

} // namespace penshape::drivers
