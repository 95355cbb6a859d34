#pragma once
// HID report descriptors of pen tablets, written by the project (no device's bytes copied): a
// standard Digitizer/Pen application as the HID Usage Tables describe it, for the layouts the
// drivers decode — with or without a report ID, 16- or 24-bit coordinates, 8- to 16-bit
// pressure, optional tilt, physical size in centimetres or inches. Tests parse these instead of
// real devices' descriptors; `penshape synthesize-recording` takes them to make recordings.
#include <cstdint>
#include <string>
#include <vector>

namespace penshape::gen {

struct PenDescriptorSpec {
  std::string name;           // for messages and file names
  std::uint8_t report_id = 0; // 0: no report ID byte
  std::int32_t x_max = 0;     // logical maxima (minima are 0)
  std::int32_t y_max = 0;
  double width_mm = 0.0; // the active area
  double height_mm = 0.0;
  std::uint32_t coordinate_bits = 16;
  std::int32_t pressure_max = 0;
  std::uint32_t pressure_bits = 16;
  bool tilt = false;          // X/Y tilt in degrees, -60..60, 8 bits each
  bool inches = false;        // physical size in inches (else centimetres)
  bool barrel_buttons = true; // barrel switch and secondary barrel switch
};

// The descriptor's bytes.
std::vector<std::uint8_t> pen_descriptor(const PenDescriptorSpec& spec);

// A digitizer whose pen reports the descriptor does not describe: one vendor-defined input
// report of `report_bytes` bytes (ID byte included) with this ID. Tablets like this speak a
// vendor protocol the drivers pick by VID/PID (e.g. Wacom's Graphire protocol).
std::vector<std::uint8_t> vendor_pen_descriptor(std::uint8_t report_id, int report_bytes);

// Layouts like the tablets the drivers support (small and large, with and without report IDs,
// tilt, inch units): what the tests iterate over.
const std::vector<PenDescriptorSpec>& pen_descriptor_specs();

} // namespace penshape::gen
