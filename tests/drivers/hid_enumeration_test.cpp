#include "penshape/drivers/hid_enumeration.hpp"

#include "penshape/drivers/device_manager.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace penshape::drivers {
namespace {

TEST(HidEnumeration, WorksWithOrWithoutDevices) {
  // CI has no /dev/hidraw*: hidapi must still initialise and return a (possibly empty) list.
  const auto devices = enumerate_hid_devices();
  for (const auto& d : devices) EXPECT_FALSE(d.path.empty());
  EXPECT_EQ(enumerate_hid_devices().size(), devices.size());
}

TEST(HidEnumeration, LibraryVersions) {
  const auto v = device_library_versions();
  ASSERT_EQ(v.size(), 2U);
  EXPECT_EQ(v[0].rfind("hidapi 0.", 0), 0U) << v[0];
  EXPECT_EQ(v[1].rfind("libusb 1.", 0), 0U) << v[1];
}

} // namespace
} // namespace penshape::drivers

namespace penshape::drivers {
namespace {

// The live backend on a machine with or without tablets: scanning works, waiting for hotplug
// blocks until its timeout or a wake() (no busy loop), and a manager on it starts and stops.
TEST(HidrawBackend, ScanWaitAndWake) {
  auto backend = make_hidraw_backend();
  for (const auto& c : backend->scan()) EXPECT_FALSE(c.key.empty());
  const auto t0 = std::chrono::steady_clock::now();
  backend->wake();
  backend->wait_for_change(std::chrono::seconds(30)); // returns at once: woken
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20));
  backend->wait_for_change(std::chrono::milliseconds(20)); // returns after its timeout
}

TEST(HidrawBackend, ManagerStartsAndStops) {
  DeviceManager m(make_hidraw_backend(), {});
  m.start();
  m.rescan();
  m.stop();
  EXPECT_TRUE(m.devices().empty());
}

} // namespace
} // namespace penshape::drivers
