#pragma once
// Lists the HID devices the hidraw backend of hidapi can see. No geometry here.
#include <cstdint>
#include <string>
#include <vector>

namespace penshape::drivers {

struct HidDeviceEntry {
  std::string path; // e.g. /dev/hidraw3
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::string manufacturer;
  std::string product;
  std::string serial;
  int interface_number = -1;
  std::uint16_t usage_page = 0;
  std::uint16_t usage = 0;
};

// Every HID device visible now (empty on a machine without any, e.g. CI).
// Throws std::runtime_error when hidapi cannot initialise.
std::vector<HidDeviceEntry> enumerate_hid_devices();

// Version strings of the device libraries in use, e.g. "hidapi 0.13.1", "libusb 1.0.26".
std::vector<std::string> device_library_versions();

} // namespace penshape::drivers
