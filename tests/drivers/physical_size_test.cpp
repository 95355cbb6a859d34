// Where a device's physical size comes from: the tablet table (applied to the maxima actually
// decoded), the descriptor's units, a UC-Logic probe by vendor ID, the user's configuration, or
// nowhere (resolution 0 and a note, never device units taken as millimetres).
#include <gtest/gtest.h>

#include <algorithm>
#include <condition_variable>
#include <mutex>

#include "penshape/drivers/device_manager.hpp"
#include "penshape/drivers/device_profile.hpp"

namespace penshape::drivers {
namespace {

using Bytes = std::vector<std::uint8_t>;

// A pen (report 2: tip switch, 16-bit X and Y of 0..32767) with no physical extents or unit, as
// a firmware-mode descriptor like the Deco 03's gives it.
const Bytes kNoUnits = {0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01, 0x85, 0x02, 0x09, 0x20, 0xA1, 0x00,
                        0x09, 0x42, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x01, 0x81, 0x02,
                        0x75, 0x07, 0x81, 0x03, 0x05, 0x01, 0x09, 0x30, 0x26, 0xFF, 0x7F, 0x75,
                        0x10, 0x95, 0x01, 0x81, 0x02, 0x09, 0x31, 0x81, 0x02, 0xC0, 0xC0};

bool has_note(const DeviceProfile& p, const std::string& what) {
  return std::any_of(p.notes.begin(), p.notes.end(),
                     [&](const std::string& n) { return n.find(what) != std::string::npos; });
}

TEST(PhysicalSize, UnknownTabletWithoutUnitsHasNoSizeUntilConfigured) {
  DeviceProfile p = build_profile({Bus::kUsb, 0x1234, 0x5678, "no-name"}, kNoUnits);
  ASSERT_TRUE(p.has_pen());
  EXPECT_EQ(p.family, "hid");
  EXPECT_EQ(p.info.x_max, 32767);
  EXPECT_EQ(p.size_source, SizeSource::kUnknown);
  EXPECT_EQ(p.info.x_resolution, 0.0); // never 1 unit = 1 mm
  EXPECT_EQ(p.info.width_mm(), 0.0);
  EXPECT_TRUE(has_note(p, "physical size unknown"));
  EXPECT_FALSE(apply_configured_size(p, 0, 95)); // a size needs both sides
  EXPECT_TRUE(apply_configured_size(p, 160, 100));
  EXPECT_EQ(p.size_source, SizeSource::kConfig);
  EXPECT_DOUBLE_EQ(p.info.x_resolution, 32767 / 160.0);
  EXPECT_DOUBLE_EQ(p.info.width_mm(), 160.0);
  EXPECT_DOUBLE_EQ(p.info.height_mm(), 100.0);
  EXPECT_FALSE(apply_configured_size(p, 10, 10)); // once known, the config does not override
}

TEST(PhysicalSize, TableSizeAppliesToTheMaximaActuallyDecoded) {
  // XP-Pen Deco 01 V2 in firmware mode: the descriptor's 32767 units span the table's 254 mm
  // (not the vendor mode's 50800).
  const DeviceProfile p = build_profile({Bus::kUsb, 0x28bd, 0x0905, ""}, kNoUnits);
  EXPECT_EQ(p.family, "xppen");
  EXPECT_EQ(p.info.x_max, 32767);
  EXPECT_EQ(p.size_source, SizeSource::kTable);
  EXPECT_NEAR(p.info.width_mm(), 254.0, 1e-9);
  EXPECT_NEAR(p.info.height_mm(), 158.75, 1e-9);
}

TEST(PhysicalSize, HuionModelWithoutRowIsProbedByVendor) {
  // 256c:ffff is in no row; Huion's VID asks for string 200, whose parameters give maxima and
  // resolution (HS610's answer: 50800 x 31750 at 5080 lpi = 200 units/mm).
  EXPECT_EQ(find_tablet(0x256c, 0xffff), nullptr);
  EXPECT_EQ(vendor_string_indexes(0x256c, 0xffff), (std::vector<std::uint8_t>{200, 100}));
  EXPECT_TRUE(vendor_string_indexes(0x1234, 0x5678).empty());
  const Bytes s200 = {0x13, 0x03, 0x70, 0xC6, 0x00, 0x06, 0x7C, 0x00, 0xFF, 0x1F, 0xD8, 0x13};
  const DeviceProfile p = build_profile({Bus::kUsb, 0x256c, 0xffff, ""}, {}, {{200, s200}});
  ASSERT_TRUE(p.has_pen());
  EXPECT_EQ(p.family, "uclogic");
  EXPECT_EQ(p.size_source, SizeSource::kProbe);
  EXPECT_EQ(p.info.x_max, 50800);
  EXPECT_DOUBLE_EQ(p.info.x_resolution, 200.0);
  EXPECT_TRUE(has_note(p, "by vendor ID"));
  // The rows' device-string indexes are read too (201 for the Huion models sharing 006d).
  const auto idx = vendor_string_indexes(0x256c, 0x006d);
  EXPECT_NE(std::find(idx.begin(), idx.end(), 201), idx.end());
  EXPECT_NE(std::find(idx.begin(), idx.end(), 200), idx.end());
}

TEST(PhysicalSize, DeviceManagerTakesTheConfiguredSizeForAnUnsizedTablet) {
  std::mutex m;
  std::condition_variable cv;
  std::vector<AttachedDevice> attached;
  DeviceCallbacks callbacks;
  callbacks.on_attach = [&](const AttachedDevice& d) {
    std::lock_guard lock(m);
    attached.push_back(d);
    cv.notify_all();
  };
  DeviceManagerOptions options;
  options.configured_size = [](std::uint16_t vid, std::uint16_t pid) {
    return vid == 0x1234 && pid == 0x5678 ? std::optional<std::pair<double, double>>({160, 100})
                                          : std::nullopt;
  };
  DeviceManager manager(nullptr, callbacks, options);
  Recording rec;
  rec.identity = {Bus::kUsb, 0x1234, 0x5678, "configured"};
  rec.has_identity = true;
  rec.descriptor = kNoUnits;
  rec.events.push_back({0, {0x02, 0x01, 0x10, 0x00, 0x20, 0x00}});
  (void)manager.attach_replay(rec, ReplaySpeed::kAsFastAsPossible);
  rec.identity.product_id = 0x5679; // not configured: stays unknown
  (void)manager.attach_replay(rec, ReplaySpeed::kAsFastAsPossible);
  std::unique_lock lock(m);
  ASSERT_TRUE(cv.wait_for(lock, std::chrono::seconds(10), [&] { return attached.size() == 2; }));
  std::sort(attached.begin(), attached.end(),
            [](const auto& a, const auto& b) { return a.tablet.product_id < b.tablet.product_id; });
  EXPECT_EQ(attached[0].size_source, SizeSource::kConfig);
  EXPECT_DOUBLE_EQ(attached[0].tablet.width_mm(), 160.0);
  EXPECT_EQ(attached[1].size_source, SizeSource::kUnknown);
  EXPECT_EQ(attached[1].tablet.x_resolution, 0.0);
  lock.unlock();
  manager.stop();
}

} // namespace
} // namespace penshape::drivers
