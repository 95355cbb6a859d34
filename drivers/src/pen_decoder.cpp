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

// Report ID -> 1 + the first layout that claims it (0: none). IDs no layout claims go to the
// first any-ID layout (decode's loop skips the others).
std::array<std::uint8_t, 256> index_by_report_id(const std::vector<PenLayout>& pens) {
  std::array<std::uint8_t, 256> index{};
  for (std::size_t i = 0; i < pens.size(); ++i) {
    if (pens[i].any_report_id) continue;
    auto& slot = index[pens[i].report_id];
    if (slot == 0) slot = static_cast<std::uint8_t>(i + 1);
  }
  const auto any =
      std::find_if(pens.begin(), pens.end(), [](const PenLayout& l) { return l.any_report_id; });
  if (any != pens.end()) {
    const auto slot_value = static_cast<std::uint8_t>(any - pens.begin() + 1);
    for (auto& slot : index) {
      if (slot == 0) slot = slot_value;
    }
  }
  return index;
}

// The shortest input report of each ID the descriptor declares (0: none).
std::array<std::uint32_t, 256> shortest_reports(const ParsedDescriptor& descriptor) {
  std::array<std::uint32_t, 256> shortest{};
  for (const auto& r : descriptor.reports) {
    if (r.type != ReportType::kInput || r.fields.empty()) continue;
    auto& m = shortest[r.report_id];
    m = m == 0 ? std::max(1U, r.size_bytes()) : std::min(m, std::max(1U, r.size_bytes()));
  }
  return shortest;
}

double read_tilt(std::span<const std::uint8_t> r, const PenField& f, const PenLayout& l) {
  return static_cast<double>(read_value(r, f) - f.logical_minimum) * l.tilt_scale + l.tilt_offset;
}

} // namespace

PenDecoder::PenDecoder(std::vector<PenLayout> pens, const ParsedDescriptor* descriptor)
    : pens_(std::move(pens)) {
  if (pens_.size() > 255) throw std::invalid_argument("PenDecoder: more than 255 pen layouts");
  if (!pens_.empty()) uses_report_ids_ = pens_.front().uses_report_id;
  for (const auto& l : pens_) {
    if (l.uses_report_id != uses_report_ids_) {
      throw std::invalid_argument("PenDecoder: layouts disagree on report IDs");
    }
  }
  pen_index_ = index_by_report_id(pens_);
  // Secondary layouts (e.g. a mouse-mode report beside the digitizer one) are rescaled so
  // every sample is in the primary layout's units, which the TabletInfo describes.
  for (const auto& l : pens_) {
    const PenLayout& p = pens_.front();
    const auto ratio = [](double to, double from) { return from > 0 && to > 0 ? to / from : 1.0; };
    scales_.push_back(Scale{ratio(p.x_max(), l.x_max()), ratio(p.y_max(), l.y_max()),
                            ratio(p.pressure_max(), l.pressure_max())});
  }
  if (descriptor != nullptr) {
    if (pens_.empty()) uses_report_ids_ = descriptor->uses_report_ids;
    other_min_bytes_ = shortest_reports(*descriptor);
  }
}

PenSample PenDecoder::read_sample(std::span<const std::uint8_t> report, std::size_t layout,
                                  std::int64_t time_us) const {
  const PenLayout& l = pens_[layout];
  const Scale& s = scales_[layout];
  PenSample out;
  out.time_us = time_us;
  out.x = clamp_to<std::int32_t>(s.rescale(read_value(report, l.x) - l.x.logical_minimum, s.x));
  out.y = clamp_to<std::int32_t>(s.rescale(read_value(report, l.y) - l.y.logical_minimum, s.y));
  if (l.pressure.present()) {
    out.pressure = static_cast<std::uint32_t>(std::max<std::int64_t>(
        0, s.rescale(read_value(report, l.pressure) - l.pressure.logical_minimum, s.pressure)));
  }
  if (l.tilt_x.present()) {
    out.tilt_x = clamp_to<std::int16_t>(std::llround(read_tilt(report, l.tilt_x, l)));
    out.tilt_y = clamp_to<std::int16_t>(std::llround(read_tilt(report, l.tilt_y, l)));
  }
  if (read_flag(report, l.barrel1)) out.buttons |= kBarrel1;
  if (read_flag(report, l.barrel2)) out.buttons |= kBarrel2;
  if (read_flag(report, l.barrel3)) out.buttons |= kBarrel3;
  if (read_flag(report, l.eraser) || read_flag(report, l.invert)) out.buttons |= kEraser;
  out.tip = l.tip.present() ? read_flag(report, l.tip) : out.pressure > l.tip_pressure_threshold;
  // Without an in-range bit, a report only arrives while the pen is in range.
  out.in_range = l.in_range.present() ? read_flag(report, l.in_range) : true;
  if (out.tip) out.in_range = true;
  return out;
}

// A report no pen layout decoded: another report the descriptor declares, or junk.
DecodeStatus PenDecoder::not_a_pen(std::span<const std::uint8_t> report, std::uint8_t id,
                                   bool known) const {
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
    out = read_sample(report, i, time_us);
    return DecodeStatus::kPen;
  }
  return not_a_pen(report, id, known);
}

} // namespace penshape::drivers
