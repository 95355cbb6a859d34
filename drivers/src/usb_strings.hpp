#pragma once
// libusb helpers for the live backend: raw string descriptors of the USB device behind a hidraw
// node, and hotplug notification. Internal to drivers/.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "penshape/drivers/device_profile.hpp"

namespace penshape::drivers::detail {

// USB bus number and device address of the device a hidraw node belongs to (from sysfs).
struct UsbAddress {
  int bus = -1;
  int address = -1;
};
UsbAddress usb_address_of_hidraw(const std::string& hidraw_path);

// Reads raw string descriptors (bLength, 0x03, payload; language 0x0409). Indexes the device
// does not answer are left out. Throws std::runtime_error when the device cannot be opened.
VendorStrings read_usb_strings(UsbAddress where, std::span<const std::uint8_t> indexes);

// Calls `notify` (on libusb's event thread) whenever a USB device arrives or leaves; does
// nothing on platforms without libusb hotplug support. Destruction stops the event thread.
class UsbHotplug {
 public:
  explicit UsbHotplug(std::function<void()> notify);
  ~UsbHotplug();
  UsbHotplug(const UsbHotplug&) = delete;
  UsbHotplug& operator=(const UsbHotplug&) = delete;
  [[nodiscard]] bool active() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace penshape::drivers::detail
