#include "usb_strings.hpp"

#include <libusb.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace penshape::drivers::detail {
namespace {

int read_int_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  int v = -1;
  in >> v;
  return in ? v : -1;
}

struct Context {
  libusb_context* ctx = nullptr;
  Context() {
    if (libusb_init(&ctx) != 0) throw std::runtime_error("libusb_init failed");
  }
  ~Context() { libusb_exit(ctx); }
};

} // namespace

UsbAddress usb_address_of_hidraw(const std::string& hidraw_path) {
  namespace fs = std::filesystem;
  const std::string node = fs::path(hidraw_path).filename().string();
  std::error_code ec;
  fs::path dir = fs::canonical(fs::path("/sys/class/hidraw") / node / "device", ec);
  if (ec) return {};
  // Walk up from the HID device through the USB interface to the USB device.
  for (int depth = 0; depth < 6 && !dir.empty() && dir != dir.root_path(); ++depth) {
    if (fs::exists(dir / "busnum") && fs::exists(dir / "devnum")) {
      return {read_int_file(dir / "busnum"), read_int_file(dir / "devnum")};
    }
    dir = dir.parent_path();
  }
  return {};
}

VendorStrings read_usb_strings(UsbAddress where, std::span<const std::uint8_t> indexes) {
  VendorStrings out;
  if (where.bus < 0) return out;
  const Context c;
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(c.ctx, &list);
  libusb_device_handle* handle = nullptr;
  for (ssize_t i = 0; i < n; ++i) {
    if (libusb_get_bus_number(list[i]) == where.bus &&
        libusb_get_device_address(list[i]) == where.address) {
      const int rc = libusb_open(list[i], &handle);
      if (rc != 0) {
        libusb_free_device_list(list, 1);
        throw std::runtime_error(std::string("libusb_open: ") + libusb_error_name(rc) +
                                 " (is the udev rule from packaging/ installed?)");
      }
      break;
    }
  }
  libusb_free_device_list(list, 1);
  if (handle == nullptr) return out;
  for (const std::uint8_t index : indexes) {
    unsigned char buf[256];
    const int got = libusb_get_string_descriptor(handle, index, 0x0409, buf, sizeof buf);
    if (got >= 2 && buf[1] == LIBUSB_DT_STRING) {
      out[index].assign(buf, buf + std::min<int>(got, buf[0] > 0 ? buf[0] : got));
    }
  }
  libusb_close(handle);
  return out;
}

struct UsbHotplug::Impl {
  std::function<void()> notify;
  libusb_context* ctx = nullptr;
  libusb_hotplug_callback_handle handle{};
  std::atomic<bool> stop{false};
  std::thread events;
  bool registered = false;

  static int callback(libusb_context*, libusb_device*, libusb_hotplug_event, void* self) {
    static_cast<Impl*>(self)->notify();
    return 0; // stay registered
  }
};

UsbHotplug::UsbHotplug(std::function<void()> notify) : impl_(std::make_unique<Impl>()) {
  impl_->notify = std::move(notify);
  if (libusb_init(&impl_->ctx) != 0) {
    impl_->ctx = nullptr;
    return;
  }
  if (libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG) == 0) return;
  const int rc = libusb_hotplug_register_callback(
      impl_->ctx,
      static_cast<libusb_hotplug_event>(LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED |
                                        LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT),
      LIBUSB_HOTPLUG_NO_FLAGS, LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY,
      LIBUSB_HOTPLUG_MATCH_ANY, &Impl::callback, impl_.get(), &impl_->handle);
  if (rc != LIBUSB_SUCCESS) return;
  impl_->registered = true;
  Impl* impl = impl_.get();
  impl_->events = std::thread([impl] {
    // Blocks in poll() inside libusb; the timeout only bounds how late `stop` is noticed.
    while (!impl->stop) {
      timeval tv{0, 500000};
      libusb_handle_events_timeout_completed(impl->ctx, &tv, nullptr);
    }
  });
}

UsbHotplug::~UsbHotplug() {
  impl_->stop = true;
  if (impl_->registered) libusb_hotplug_deregister_callback(impl_->ctx, impl_->handle);
  if (impl_->events.joinable()) impl_->events.join();
  if (impl_->ctx != nullptr) libusb_exit(impl_->ctx);
}

bool UsbHotplug::active() const { return impl_->registered; }

} // namespace penshape::drivers::detail
