#pragma once
// Vendor report formats the descriptor does not describe, expressed as PenLayouts so the one
// PenDecoder reads them. Facts from the public Linux drivers (hid-uclogic, wacom_wac) and
// OpenTabletDriver; the code is ours.
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

// Wacom Graphire-family pen report (ID 2, 8 bytes; PenPartner/PenStation2, Graphire, Volito):
// byte 1 bit 7 in range, bits 5-6 tool (0 pen, 1 eraser, 2 mouse: not the pen), bit 0 tip,
// bits 1-2 side switches; X, Y little-endian 16-bit at bytes 2 and 4; 10-bit pressure in byte 6
// plus the low two bits of byte 7. Maxima and resolution from the tablet table row.
PenLayout wacom_graphire_pen_layout(const TabletSpec& spec);

// Wacom Bamboo-family pen report (ID 2, 9 or 10 bytes; Bamboo, Intuos PT, One by Wacom CTL-472)
// after the mode-switch feature report 02 02: byte 1 bit 7 in range, bit 6 position valid
// (proximity), bit 5 pressure and buttons valid, bit 3 eraser, bit 0 tip, bits 1-2 side
// switches; X, Y, pressure little-endian 16-bit at bytes 2, 4, 6.
PenLayout wacom_bamboo_pen_layout(const TabletSpec& spec);

// Wacom Intuos-family pen reports (ID 2, 10 bytes; Intuos 2-5, Intuos Pro PTH-x51, Intuos
// CTH-490) after the mode switch. Two layouts share the ID, told apart by byte 1:
//  - the general pen packet, (byte1 & 0xB8) == 0xA0: X = big-endian 16 bits at byte 2 shifted
//    left once plus bit 1 of byte 9; Y likewise at byte 4 plus bit 0 of byte 9; pressure
//    11 bits = byte 6 (bits 3-10), bits 6-7 of byte 7 (bits 1-2), bit 0 of byte 1 (bit 0);
//    tilt X = bits 0-5 of byte 7 and bit 7 of byte 8, tilt Y = bits 0-6 of byte 8, each 0..127
//    centred on 64 (degrees); side switches bits 1 and 2 of byte 1; tip when pressure > 10.
//  - the leaving-proximity packet, (byte1 & 0xFE) == 0x80: in range false.
// Tool-announcement packets (0xC2…) carry no position and count as other reports.
std::vector<PenLayout> wacom_intuos_pen_layouts(const TabletSpec& spec);

// XP-Pen/Ugee vendor-mode pen report after output report 02 B0 02|04 (ID 2, 10 bytes): byte 1
// 0xA0 in range (bit 6 set: out of range), bit 0 tip, bits 1-2 side switches, 0xF0 pad frames;
// X, Y, pressure little-endian 16-bit at bytes 2, 4, 6; signed tilt at bytes 8 and 9.
PenLayout xppen_pen_layout(const TabletSpec& spec);

} // namespace penshape::drivers
