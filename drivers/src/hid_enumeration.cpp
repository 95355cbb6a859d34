#include "penshape/drivers/hid_enumeration.hpp"

#include <hidapi.h>
#include <libusb.h>

#include <memory>
#include <stdexcept>

namespace penshape::drivers {
namespace {

std::string narrow(const wchar_t* w) {
  std::string out;
  if (w == nullptr) return out;
  for (; *w != L'\0'; ++w) {
    // HID strings are almost always ASCII; anything else becomes '?' rather than mojibake.
    out.push_back(*w < 0x80 ? static_cast<char>(*w) : '?');
  }
  return out;
}

struct HidInit {
  HidInit() {
    if (hid_init() != 0) throw std::runtime_error("hidapi: hid_init failed");
  }
};

} // namespace

std::vector<HidDeviceEntry> enumerate_hid_devices() {
  // hid_init is reference-free and idempotent; it runs once per process.
  static const HidInit init;
  std::vector<HidDeviceEntry> out;
  std::unique_ptr<hid_device_info, decltype(&hid_free_enumeration)> list(hid_enumerate(0, 0),
                                                                         &hid_free_enumeration);
  for (const hid_device_info* d = list.get(); d != nullptr; d = d->next) {
    HidDeviceEntry e;
    e.path = d->path != nullptr ? d->path : "";
    e.vendor_id = d->vendor_id;
    e.product_id = d->product_id;
    e.manufacturer = narrow(d->manufacturer_string);
    e.product = narrow(d->product_string);
    e.serial = narrow(d->serial_number);
    e.interface_number = d->interface_number;
    e.usage_page = d->usage_page;
    e.usage = d->usage;
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<std::string> device_library_versions() {
  const hid_api_version* hv = hid_version();
  const libusb_version* uv = libusb_get_version();
  return {
      "hidapi " + std::to_string(hv->major) + "." + std::to_string(hv->minor) + "." +
          std::to_string(hv->patch),
      "libusb " + std::to_string(uv->major) + "." + std::to_string(uv->minor) + "." +
          std::to_string(uv->micro),
  };
}

} // namespace penshape::drivers
