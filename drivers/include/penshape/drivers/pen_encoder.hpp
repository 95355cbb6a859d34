#pragma once
// The inverse of the pen decoder: a PenSample written as the input report a layout describes.
// Used to synthesize recordings of real tablets (recordings/) and by tests that push samples
// through the real decode path. Values are clamped to each field's logical range.
#include <cstdint>
#include <vector>

#include "penshape/drivers/pen_layout.hpp"
#include "penshape/types/pen_sample.hpp"

namespace penshape::drivers {

// The report bytes (with the report ID byte first when the layout uses IDs), min_report_bytes
// long. Vendor layouts that share a report ID are told apart by their match byte, which is set.
std::vector<std::uint8_t> encode_pen_report(const PenLayout& layout, const PenSample& sample);

} // namespace penshape::drivers
