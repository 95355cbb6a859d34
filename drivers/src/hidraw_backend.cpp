// The live backend: hidapi's hidraw backend for enumeration and I/O, sysfs (or HIDIOCGRDESC)
// for report descriptors, libusb for UC-Logic string descriptors and hotplug callbacks, and a
// libudev monitor on the hidraw subsystem (hidraw nodes appear a little after the USB device).
#include <fcntl.h>
#include <hidapi.h>
#include <libudev.h>
#include <linux/hidraw.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "init_reports.hpp"
#include "penshape/drivers/device_manager.hpp"
#include "penshape/drivers/live_recorder.hpp"
#include "usb_strings.hpp"

namespace penshape::drivers {
namespace {

namespace fs = std::filesystem;

std::string narrow(const wchar_t* w) {
  std::string out;
  for (; w != nullptr && *w != L'\0'; ++w) out.push_back(*w < 0x80 ? static_cast<char>(*w) : '?');
  return out;
}

struct HidInit {
  HidInit() {
    if (hid_init() != 0) throw std::runtime_error("hidapi: hid_init failed");
  }
};
void ensure_hid_init() { static const HidInit init; }

// Report descriptor of a hidraw node: sysfs first, the ioctl as fallback.
std::vector<std::uint8_t> read_descriptor(const std::string& path) {
  const std::string node = fs::path(path).filename().string();
  std::ifstream in(fs::path("/sys/class/hidraw") / node / "device/report_descriptor",
                   std::ios::binary);
  if (in) {
    std::vector<std::uint8_t> out((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    if (!out.empty()) return out;
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  int size = 0;
  std::vector<std::uint8_t> out;
  hidraw_report_descriptor desc{};
  if (::ioctl(fd, HIDIOCGRDESCSIZE, &size) == 0 && size > 0 &&
      size <= static_cast<int>(sizeof desc.value)) {
    desc.size = static_cast<std::uint32_t>(size);
    if (::ioctl(fd, HIDIOCGRDESC, &desc) == 0) out.assign(desc.value, desc.value + desc.size);
  }
  ::close(fd);
  return out;
}

// Bus and name from the HID device's uevent (HID_ID=0003:0000056A:00000061, HID_NAME=…); the
// kernel's name and phys too when asked (what hid-recorder writes as N: and P:).
void read_uevent(const std::string& path, DeviceIdentity& id, std::string* hid_name = nullptr,
                 std::string* phys = nullptr) {
  const std::string node = fs::path(path).filename().string();
  std::ifstream in(fs::path("/sys/class/hidraw") / node / "device/uevent");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("HID_ID=", 0) == 0) {
      id.bus = static_cast<Bus>(std::stoul(line.substr(7, 4), nullptr, 16));
    } else if (line.rfind("HID_NAME=", 0) == 0) {
      if (id.name.empty()) id.name = line.substr(9);
      if (hid_name != nullptr) *hid_name = line.substr(9);
    } else if (line.rfind("HID_PHYS=", 0) == 0 && phys != nullptr) {
      *phys = line.substr(9);
    }
  }
}

class HidapiSource final : public ReportSource {
 public:
  explicit HidapiSource(hid_device* dev) : dev_(dev), start_(std::chrono::steady_clock::now()) {}
  ~HidapiSource() override { hid_close(dev_); }

  ReadStatus read(std::vector<std::uint8_t>& bytes, std::int64_t& time_us,
                  std::chrono::milliseconds timeout) override {
    if (interrupted_) return ReadStatus::kEnd;
    const int n =
        hid_read_timeout(dev_, buffer_.data(), buffer_.size(), static_cast<int>(timeout.count()));
    if (n < 0) return ReadStatus::kGone;
    if (interrupted_) return ReadStatus::kEnd;
    if (n == 0) return ReadStatus::kTimeout;
    bytes.assign(buffer_.begin(), buffer_.begin() + n);
    time_us = now_us();
    return ReadStatus::kReport;
  }
  std::int64_t now_us() const override {
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() -
                                                                 start_)
        .count();
  }
  // hid_read_timeout cannot be woken; the reader loop's poll period bounds the delay.
  void interrupt() override { interrupted_ = true; }

 private:
  hid_device* dev_;
  std::vector<std::uint8_t> buffer_ = std::vector<std::uint8_t>(kMaxReportBytes);
  std::chrono::steady_clock::time_point start_;
  std::atomic<bool> interrupted_{false};
};

std::unique_ptr<ReportSource> open_hidraw(const std::string& path,
                                          const std::vector<InitStep>& init) {
  ensure_hid_init();
  hid_device* dev = hid_open_path(path.c_str());
  if (dev == nullptr) throw std::runtime_error("cannot open " + path + " (permissions?)");
  auto source = std::make_unique<HidapiSource>(dev);
  send_init_reports(path, init, [dev](const InitStep& step) {
    return step.kind == InitStep::Kind::kFeatureReport
               ? hid_send_feature_report(dev, step.bytes.data(), step.bytes.size())
               : hid_write(dev, step.bytes.data(), step.bytes.size());
  });
  return source;
}

class HidrawBackend final : public DeviceBackend {
 public:
  HidrawBackend() : hotplug_([this] { wake(); }) {
    wake_fd_ = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
    udev_ = udev_new();
    if (udev_ != nullptr) {
      monitor_ = udev_monitor_new_from_netlink(udev_, "udev");
      if (monitor_ != nullptr &&
          (udev_monitor_filter_add_match_subsystem_devtype(monitor_, "hidraw", nullptr) < 0 ||
           udev_monitor_enable_receiving(monitor_) < 0)) {
        udev_monitor_unref(monitor_);
        monitor_ = nullptr;
      }
    }
  }
  ~HidrawBackend() override {
    if (monitor_ != nullptr) udev_monitor_unref(monitor_);
    if (udev_ != nullptr) udev_unref(udev_);
    if (wake_fd_ >= 0) ::close(wake_fd_);
  }

  std::vector<DeviceCandidate> scan() override {
    ensure_hid_init();
    std::vector<DeviceCandidate> out;
    hid_device_info* list = hid_enumerate(0, 0);
    for (const hid_device_info* d = list; d != nullptr; d = d->next) {
      if (d->path == nullptr) continue;
      DeviceCandidate c;
      c.key = d->path;
      c.identity.vendor_id = d->vendor_id;
      c.identity.product_id = d->product_id;
      c.identity.name = narrow(d->product_string);
      read_uevent(c.key, c.identity, &c.hid_name, &c.phys);
      // Only tablets we know, or anything whose descriptor declares a pen.
      c.descriptor = read_descriptor(c.key);
      if (find_tablet(d->vendor_id, d->product_id) == nullptr) {
        try {
          if (c.descriptor.empty() ||
              find_pen_layouts(parse_report_descriptor(c.descriptor)).empty()) {
            continue;
          }
        } catch (const DescriptorError&) {
          continue;
        }
      }
      out.push_back(std::move(c));
    }
    hid_free_enumeration(list);
    return out;
  }

  VendorStrings read_vendor_strings(const DeviceCandidate& device,
                                    std::span<const std::uint8_t> indexes) override {
    return detail::read_usb_strings(detail::usb_address_of_hidraw(device.key), indexes);
  }

  std::unique_ptr<ReportSource> open(const DeviceCandidate& device,
                                     const std::vector<InitStep>& init) override {
    return open_hidraw(device.key, init);
  }

  void wait_for_change(std::chrono::milliseconds timeout) override {
    pollfd fds[2]{};
    nfds_t n = 0;
    fds[n++] = {wake_fd_, POLLIN, 0};
    if (monitor_ != nullptr) fds[n++] = {udev_monitor_get_fd(monitor_), POLLIN, 0};
    if (::poll(fds, n, static_cast<int>(timeout.count())) <= 0) return;
    std::uint64_t count = 0;
    if ((fds[0].revents & POLLIN) != 0) (void)::read(wake_fd_, &count, sizeof count);
    if (n > 1 && (fds[1].revents & POLLIN) != 0) {
      udev_device* dev = udev_monitor_receive_device(monitor_);
      if (dev != nullptr) udev_device_unref(dev);
    }
  }

  void wake() override {
    const std::uint64_t one = 1;
    if (wake_fd_ >= 0) (void)::write(wake_fd_, &one, sizeof one);
  }

 private:
  int wake_fd_ = -1;
  udev* udev_ = nullptr;
  udev_monitor* monitor_ = nullptr;
  detail::UsbHotplug hotplug_; // last: its thread calls wake() until destroyed
};

} // namespace

std::unique_ptr<DeviceBackend> make_hidraw_backend() { return std::make_unique<HidrawBackend>(); }

std::size_t record_hidraw(const std::string& path, std::ostream& out, const std::atomic<bool>& stop,
                          std::chrono::milliseconds max_duration) {
  ensure_hid_init();
  Recording header;
  header.descriptor = read_descriptor(path);
  std::string hid_name;
  read_uevent(path, header.identity, &hid_name, &header.phys);
  if (!hid_name.empty()) header.identity.name = hid_name;
  {
    hid_device_info* info = hid_enumerate(0, 0);
    for (const hid_device_info* d = info; d != nullptr; d = d->next) {
      if (d->path != nullptr && path == d->path) {
        header.identity.vendor_id = d->vendor_id;
        header.identity.product_id = d->product_id;
        header.has_identity = true;
      }
    }
    hid_free_enumeration(info);
  }
  std::vector<InitStep> init;
  if (find_tablet(header.identity.vendor_id, header.identity.product_id) != nullptr) {
    const auto indexes =
        vendor_string_indexes(header.identity.vendor_id, header.identity.product_id);
    if (!indexes.empty()) {
      header.vendor_strings =
          detail::read_usb_strings(detail::usb_address_of_hidraw(path), indexes);
    }
    init = build_profile(header.identity, header.descriptor, header.vendor_strings).init;
  }
  auto source = open_hidraw(path, init);
  return record_source(*source, header, out, stop, max_duration);
}

} // namespace penshape::drivers
