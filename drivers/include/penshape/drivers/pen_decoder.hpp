#pragma once
// Turns raw input reports (bytes exactly as hidraw delivers them) into PenSamples, using pen
// layouts from the descriptor or a vendor protocol. Allocation-free and O(report length).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "penshape/drivers/hid_descriptor.hpp"
#include "penshape/drivers/pen_layout.hpp"
#include "penshape/types/pen_sample.hpp"

namespace penshape::drivers {

enum class DecodeStatus : std::uint8_t {
  kPen,   // a pen sample was produced
  kOther, // a well-formed report that is not the pen's (pad buttons, dials, mouse, touch)
  kJunk,  // empty, unknown report ID, or shorter than its report: drop and count
};

class PenDecoder {
 public:
  // `pens`: the pen layouts, first one primary. `descriptor` (optional) names the device's
  // other input reports so they count as kOther instead of junk.
  explicit PenDecoder(std::vector<PenLayout> pens, const ParsedDescriptor* descriptor = nullptr);

  // Decodes one report. On kPen `out` holds the sample (time set to `time_us`).
  DecodeStatus decode(std::span<const std::uint8_t> report, std::int64_t time_us,
                      PenSample& out) const;

  [[nodiscard]] const std::vector<PenLayout>& layouts() const { return pens_; }
  [[nodiscard]] bool has_pen() const { return !pens_.empty(); }
  [[nodiscard]] bool uses_report_ids() const { return uses_report_ids_; }

 private:
  struct Scale {
    double x = 1.0, y = 1.0, pressure = 1.0;
    // v * f + 0.5 truncated toward zero, as recordings have always decoded: half up for the
    // in-range values (>= 0), toward zero for the negative ones a junk frame can give. Clamped
    // into int64's range first, so the cast is always defined (it was undefined beyond).
    static std::int64_t rescale(std::int64_t v, double f) {
      if (f == 1.0) return v;
      constexpr double kLimit = 9223372036854774784.0; // the largest double below 2^63
      return static_cast<std::int64_t>(
          std::clamp(std::trunc(static_cast<double>(v) * f + 0.5), -kLimit, kLimit));
    }
  };
  PenSample read_sample(std::span<const std::uint8_t> report, std::size_t layout,
                        std::int64_t time_us) const;
  DecodeStatus not_a_pen(std::span<const std::uint8_t> report, std::uint8_t id, bool known) const;

  std::vector<PenLayout> pens_;
  std::vector<Scale> scales_;
  bool uses_report_ids_ = false;
  // Per report ID: index+1 of the first pen layout with that ID (0 none), and the minimum
  // length of another known input report (0 unknown).
  std::array<std::uint8_t, 256> pen_index_{};
  std::array<std::uint32_t, 256> other_min_bytes_{};
};

} // namespace penshape::drivers
