#pragma once
// A stroke: the samples from tip down to tip up, with the tablet they came from.
#include <cstdint>
#include <vector>

#include "penshape/types/pen_sample.hpp"
#include "penshape/types/tablet_info.hpp"

namespace penshape {

struct Stroke {
  std::uint64_t id = 0;           // unique per daemon run (or per recording)
  TabletInfo tablet;              // maxima and resolution the samples are in
  std::vector<PenSample> samples; // in time order; the first has tip down, the last tip up

  [[nodiscard]] bool empty() const { return samples.empty(); }
  [[nodiscard]] std::int64_t duration_us() const {
    return samples.size() < 2 ? 0 : samples.back().time_us - samples.front().time_us;
  }
};

} // namespace penshape
