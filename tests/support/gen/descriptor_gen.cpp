// The generated tablets' descriptors (descriptor_gen.hpp), written by the drivers' one HID
// descriptor writer (penshape/drivers/pen_descriptor_writer.hpp).
#include "descriptor_gen.hpp"

namespace penshape::gen {

using namespace drivers::hid_item;

std::vector<std::uint8_t> vendor_pen_descriptor(std::uint8_t report_id, int report_bytes) {
  drivers::HidItemWriter w;
  w.item(kUsagePage, 0x0D);  // Digitizers
  w.item(kUsage, 0x01);      // Digitizer
  w.item(kCollection, 0x01); // Application
  w.item(kReportId, report_id);
  w.item(kCollection, 0x00);  // Physical
  w.item(kUsagePage, 0xFF00); // vendor-defined
  w.item(kUsage, 0x01);
  w.item(kLogicalMin, 0);
  w.item(kLogicalMax, 0xFF);
  w.input(8, report_bytes - 1, kDataVarAbs);
  w.end_collection();
  w.end_collection();
  return w.take();
}

const std::vector<PenDescriptorSpec>& pen_descriptor_specs() {
  static const std::vector<PenDescriptorSpec> specs{
      // name, report id, x max, y max, width, height, coordinate bits, pressure max, bits, tilt,
      // inches, barrel buttons, tilt degrees, eraser, fine units
      {"small-8192-id7", 7, 32000, 20000, 160.0, 100.0, 16, 8191, 16, false, false, true, 60, false,
       false},
      {"medium-tilt-id2", 2, 44800, 28000, 224.0, 140.0, 16, 8191, 16, true, false, true, 60, false,
       false},
      {"large-24bit-inch", 8, 152400, 95250, 304.8, 190.5, 24, 16383, 16, true, true, true, 60,
       false, false},
      {"basic-no-id-1024", 0, 15200, 9500, 152.0, 95.0, 16, 1023, 12, false, false, false, 60,
       false, false},
      {"tiny-inch-255", 1, 5080, 3810, 50.8, 38.1, 16, 255, 8, false, true, true, 60, false, false},
  };
  return specs;
}

} // namespace penshape::gen
