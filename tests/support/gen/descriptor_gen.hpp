#pragma once
// HID report descriptors of pen tablets, written by the project (no device's bytes copied): a
// standard Digitizer/Pen application as the HID Usage Tables describe it, for the layouts the
// drivers decode — with or without a report ID, 16- or 24-bit coordinates, 8- to 16-bit
// pressure, optional tilt, physical size in centimetres or inches. Tests parse these instead of
// real devices' descriptors; `penshape synthesize-recording` takes them to make recordings.
#include <cstdint>
#include <string>
#include <vector>

#include "penshape/drivers/pen_descriptor_writer.hpp"

namespace penshape::gen {

// The drivers' pen descriptor spec (pen_descriptor_writer.hpp); the tests' layouts use its
// defaults for the re-encoding options (tilt ±60, Invert, 0.1 mm steps).
using PenDescriptorSpec = drivers::PenDescriptorSpec;

// The descriptor's bytes.
using drivers::pen_descriptor;

// A digitizer whose pen reports the descriptor does not describe: one vendor-defined input
// report of `report_bytes` bytes (ID byte included) with this ID. Tablets like this speak a
// vendor protocol the drivers pick by VID/PID (e.g. Wacom's Graphire protocol).
std::vector<std::uint8_t> vendor_pen_descriptor(std::uint8_t report_id, int report_bytes);

// Layouts like the tablets the drivers support (small and large, with and without report IDs,
// tilt, inch units): what the tests iterate over.
const std::vector<PenDescriptorSpec>& pen_descriptor_specs();

} // namespace penshape::gen
