#pragma once
// The UC-Logic vendor probe: the pen parameters a Huion/Gaomon tablet returns in USB string
// descriptor 200 (or 100), and the v1 layout that goes with string 100. Every other vendor
// format is data (report_families.hpp, data/families.tsv). Facts from the public Linux driver
// hid-uclogic and OpenTabletDriver; the code is ours.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "penshape/drivers/pen_layout.hpp"
#include "penshape/drivers/tablet_table.hpp"

namespace penshape::drivers {

// UC-Logic (Huion, Gaomon, some XP-Pen/Ugee) pen parameters, returned by USB string descriptor
// 100 (v1) or 200 (v2). Reading descriptor 200 is also what switches a tablet to vendor mode.
struct UcLogicParams {
  int version = 2; // 1: string 100, 16-bit coordinates; 2: string 200, 24-bit
  std::int32_t x_max = 0;
  std::int32_t y_max = 0;
  std::uint32_t pressure_max = 0;
  std::uint32_t resolution_lpi = 0; // lines per inch
};

// Parses the raw string descriptor (bLength, bDescriptorType 0x03, payload) of index 100
// (version 1) or 200 (version 2). Throws std::invalid_argument naming the problem (too short,
// not a string descriptor, zero maxima).
UcLogicParams parse_uclogic_params(std::span<const std::uint8_t> string_descriptor, int version);

// UC-Logic vendor-mode pen report: ID 0x08 (v2, 12 bytes, coordinates split over bytes 2-3 and
// 8 / 4-5 and 9, tilt in bytes 10-11) or ID 0x07 (v1, 8 bytes, in-range bit inverted).
// Pad frames share the ID and are told apart by byte 1 (0xE0/0xF0: not the pen).
PenLayout uclogic_pen_layout(const UcLogicParams& params);

} // namespace penshape::drivers
