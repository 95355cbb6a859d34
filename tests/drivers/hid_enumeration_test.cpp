#include "penshape/drivers/hid_enumeration.hpp"

#include <gtest/gtest.h>

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
