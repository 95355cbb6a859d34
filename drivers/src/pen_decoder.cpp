#include "penshape/drivers/pen_decoder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace penshape::drivers {
namespace {

std::int64_t read_value(std::span<const std::uint8_t> r, const PenField& f) {
  std::uint32_t v = extract_bits(r, f.bit_offset, f.bit_size);
  std::uint32_t bits = f.bit_size;
  if (f.high_bit_size > 0) {
    std::uint32_t high = extract_bits(r, f.high_bit_offset, f.high_bit_size);
    if (f.high_big_endian) {
      std::uint32_t swapped = 0;
      for (std::uint32_t i = 0; i < f.high_bit_size / 8; ++i) {
        swapped = (swapped << 8) | ((high >> (8 * i)) & 0xFFU);
      }
      high = swapped;
    }
    v |= high << bits;
    bits += f.high_bit_size;
  }
  if (f.top_bit_size > 0) {
    v |= extract_bits(r, f.top_bit_offset, f.top_bit_size) << bits;
    bits += f.top_bit_size;
  }
  return f.is_signed ? sign_extend(v, bits) : static_cast<std::int64_t>(v);
}

// The report passes a layout's match condition (mask 0: no condition).
bool matches(std::span<const std::uint8_t> r, std::uint32_t byte, std::uint8_t mask,
             std::uint8_t value, bool reject) {
  if (mask == 0) return true;
  if (byte >= r.size()) return false;
  return ((r[byte] & mask) == value) != reject;
}

bool read_flag(std::span<const std::uint8_t> r, const PenField& f) {
  if (!f.present()) return false;
  const bool set = extract_bits(r, f.bit_offset, f.bit_size) != 0;
  return set != f.inverted;
}

template <typename T>
T clamp_to(std::int64_t v) {
  return static_cast<T>(
      std::clamp<std::int64_t>(v, std::numeric_limits<T>::min(), std::numeric_limits<T>::max()));
}

} // namespace

PenDecoder::PenDecoder(std::vector<PenLayout> pens, const ParsedDescriptor* descriptor)
    : pens_(std::move(pens)) {
  if (pens_.size() > 255) throw std::invalid_argument("PenDecoder: more than 255 pen layouts");
  for (std::size_t i = 0; i < pens_.size(); ++i) {
    if (i == 0) uses_report_ids_ = pens_[i].uses_report_id;
    if (pens_[i].uses_report_id != uses_report_ids_) {
      throw std::invalid_argument("PenDecoder: layouts disagree on report IDs");
    }
    if (pens_[i].any_report_id) continue;
    auto& slot = pen_index_[pens_[i].report_id];
    if (slot == 0) slot = static_cast<std::uint8_t>(i + 1);
  }
  // IDs no layout claims go to the first any-ID layout (the loop in decode skips the others).
  for (std::size_t i = 0; i < pens_.size(); ++i) {
    if (!pens_[i].any_report_id) continue;
    for (auto& slot : pen_index_) {
      if (slot == 0) slot = static_cast<std::uint8_t>(i + 1);
    }
    break;
  }
  // Secondary layouts (e.g. a mouse-mode report beside the digitizer one) are rescaled so
  // every sample is in the primary layout's units, which the TabletInfo describes.
  for (const auto& l : pens_) {
    Scale s;
    const PenLayout& p = pens_.front();
    const auto ratio = [](double to, double from) { return from > 0 && to > 0 ? to / from : 1.0; };
    s.x = ratio(p.x_max(), l.x_max());
    s.y = ratio(p.y_max(), l.y_max());
    s.pressure = ratio(p.pressure_max(), l.pressure_max());
    scales_.push_back(s);
  }
  if (descriptor != nullptr) {
    if (pens_.empty()) uses_report_ids_ = descriptor->uses_report_ids;
    for (const auto& r : descriptor->reports) {
      if (r.type != ReportType::kInput || r.fields.empty()) continue;
      auto& m = other_min_bytes_[r.report_id];
      m = m == 0 ? std::max(1U, r.size_bytes()) : std::min(m, std::max(1U, r.size_bytes()));
    }
  }
}

DecodeStatus PenDecoder::decode(std::span<const std::uint8_t> report, std::int64_t time_us,
                                PenSample& out) const {
  if (report.empty()) return DecodeStatus::kJunk;
  const std::uint8_t id = uses_report_ids_ ? report[0] : 0;
  // Several layouts may share an ID (vendor reports told apart by a flag byte): try each.
  bool known = false;
  for (std::size_t i = pen_index_[id] == 0 ? pens_.size() : pen_index_[id] - 1U; i < pens_.size();
       ++i) {
    const PenLayout& l = pens_[i];
    if (l.report_id != id && !l.any_report_id) continue;
    known = true;
    if (report.size() < l.min_report_bytes) continue;
    if (!matches(report, l.match_byte, l.match_mask, l.match_value, l.match_reject) ||
        !matches(report, l.match2_byte, l.match2_mask, l.match2_value, l.match2_reject)) {
      continue;
    }
    out = PenSample{};
    out.time_us = time_us;
    const Scale& s = scales_[i];
    out.x = clamp_to<std::int32_t>(s.rescale(read_value(report, l.x) - l.x.logical_minimum, s.x));
    out.y = clamp_to<std::int32_t>(s.rescale(read_value(report, l.y) - l.y.logical_minimum, s.y));
    if (l.pressure.present()) {
      out.pressure = static_cast<std::uint32_t>(std::max<std::int64_t>(
          0, s.rescale(read_value(report, l.pressure) - l.pressure.logical_minimum, s.pressure)));
    }
    if (l.tilt_x.present()) {
      const double tx =
          static_cast<double>(read_value(report, l.tilt_x) - l.tilt_x.logical_minimum) *
              l.tilt_scale +
          l.tilt_offset;
      const double ty =
          static_cast<double>(read_value(report, l.tilt_y) - l.tilt_y.logical_minimum) *
              l.tilt_scale +
          l.tilt_offset;
      out.tilt_x = clamp_to<std::int16_t>(std::llround(tx));
      out.tilt_y = clamp_to<std::int16_t>(std::llround(ty));
    }
    if (read_flag(report, l.barrel1)) out.buttons |= kBarrel1;
    if (read_flag(report, l.barrel2)) out.buttons |= kBarrel2;
    if (read_flag(report, l.barrel3)) out.buttons |= kBarrel3;
    if (read_flag(report, l.eraser) || read_flag(report, l.invert)) out.buttons |= kEraser;
    out.tip = l.tip.present() ? read_flag(report, l.tip) : out.pressure > l.tip_pressure_threshold;
    // Without an in-range bit, a report only arrives while the pen is in range.
    out.in_range = l.in_range.present() ? read_flag(report, l.in_range) : true;
    if (out.tip) out.in_range = true;
    return DecodeStatus::kPen;
  }
  if (other_min_bytes_[id] != 0) {
    return report.size() >= other_min_bytes_[id] ? DecodeStatus::kOther : DecodeStatus::kJunk;
  }
  // A pen report ID that failed the length or flag test: flag mismatch means another report
  // kind sharing the ID (e.g. UC-Logic pad frames); a short report is junk.
  if (known) {
    for (const auto& l : pens_) {
      if ((l.report_id == id || l.any_report_id) && report.size() >= l.min_report_bytes) {
        return DecodeStatus::kOther;
      }
    }
  }
  return DecodeStatus::kJunk;
}

} // namespace penshape::drivers
