// The tablet table: the built-in rows parse, cover the tablets with data in ../shared/data/hid,
// and bad rows are rejected with their line number.
#include "penshape/drivers/tablet_table.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/vendor_protocols.hpp"
#include "shared_data.hpp"
#include "test_data.hpp"

namespace penshape::drivers {
namespace {

TEST(TabletTable, BuiltinCoversEveryDeviceWithSharedData) {
  PENSHAPE_SHARED_OR_SKIP(hid, "hid/wacom-hid-descriptors");
  const auto& rows = builtin_tablets();
  EXPECT_GE(rows.size(), 80U);
  for (const auto& d : testing::all_shared_descriptors()) {
    if (d.vendor_id == 0 && d.product_id == 0) continue; // collection entries without I:
    EXPECT_NE(find_tablet(d.vendor_id, d.product_id), nullptr) << d.source;
  }
  // The DIGImend tablets and their protocols.
  EXPECT_EQ(find_tablet(0x256c, 0x006d)->protocol, Protocol::kUcLogic);
  EXPECT_EQ(find_tablet(0x28bd, 0x0907)->protocol, Protocol::kXpPen);
  const TabletSpec* pp = find_tablet(0x056a, 0x0061);
  ASSERT_NE(pp, nullptr);
  EXPECT_EQ(pp->protocol, Protocol::kWacomGraphire);
  EXPECT_EQ(pp->x_max, 3250);
  const TabletSpec* intuos = find_tablet(0x056a, 0x033c);
  ASSERT_NE(intuos, nullptr);
  ASSERT_EQ(intuos->init.size(), 1U);
  EXPECT_EQ(intuos->init[0].kind, InitStep::Kind::kFeatureReport);
  EXPECT_EQ(intuos->init[0].bytes, (std::vector<std::uint8_t>{0x02, 0x02}));
}

TEST(TabletTable, UdevRulesGrantEveryTabletsNodes) {
  const std::string rules =
      read_file(std::filesystem::path(PENSHAPE_SOURCE_DIR) / "packaging/70-penshape-tablets.rules");
  for (const auto& t : builtin_tablets()) {
    char hidraw[96], usb[160];
    std::snprintf(hidraw, sizeof hidraw,
                  "KERNEL==\"hidraw*\", KERNELS==\"*:%04X:%04X.*\", TAG+=\"uaccess\"\n",
                  t.vendor_id, t.product_id);
    std::snprintf(usb, sizeof usb,
                  "SUBSYSTEM==\"usb\", ENV{DEVTYPE}==\"usb_device\", ATTR{idVendor}==\"%04x\", "
                  "ATTR{idProduct}==\"%04x\", TAG+=\"uaccess\"\n",
                  t.vendor_id, t.product_id);
    EXPECT_NE(rules.find(hidraw), std::string::npos) << t.name;
    EXPECT_NE(rules.find(usb), std::string::npos) << t.name;
  }
}

TEST(TabletTable, BadRowsNameTheirLine) {
  EXPECT_THROW((void)parse_tablet_table("# c\n056a\t0061\thid\n"), TabletTableError);
  const std::string tail = "\t-\t0\t1\t1\t1\t1\t1\t2\t-\tX\n";
  try {
    (void)parse_tablet_table("\n056a\t0061\tfoo" + tail);
    FAIL();
  } catch (const TabletTableError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("foo"), std::string::npos);
  }
  EXPECT_THROW((void)parse_tablet_table("056a\t0061\thid\tF:0\t0\t1\t1\t1\t1\t1\t2\t-\tX\n"),
               TabletTableError);
  // A device_match regex that does not compile is a bad row, not a crash at match time.
  EXPECT_THROW((void)parse_tablet_table("056a\t0061\thid\t-\t0\t1\t1\t1\t1\t1\t2\t201=(\tX\n"),
               TabletTableError);
  const auto ok = parse_tablet_table(
      "256c\t0061\tuclogic\tO:02b004 S:200\t12\t10\t20\t30\t5\t4\t2\t201=^AB;4=C\tName\n");
  ASSERT_EQ(ok.size(), 1U);
  EXPECT_EQ(ok[0].init.size(), 2U);
  EXPECT_EQ(ok[0].init[1].string_index, 200);
  EXPECT_EQ(ok[0].protocol, Protocol::kUcLogic);
  EXPECT_EQ(ok[0].report_length, 12U);
  EXPECT_DOUBLE_EQ(ok[0].x_resolution, 2.0); // 10 units over 5 mm
  EXPECT_DOUBLE_EQ(ok[0].y_resolution, 5.0);
  EXPECT_EQ(ok[0].device_match.size(), 2U);
  EXPECT_TRUE(device_strings_match(ok[0], {{201, "ABC"}, {4, "xCx"}}));
  EXPECT_FALSE(device_strings_match(ok[0], {{201, "XABC"}, {4, "C"}}));
  EXPECT_FALSE(device_strings_match(ok[0], {{201, "ABC"}})); // string 4 missing
}

TEST(UcLogicParams, ParsesTheProbedStringDescriptors) {
  // HS610 string 200 and H610 string 100, from DIGImend's probe.txt.
  const std::vector<std::uint8_t> s200 = {0x13, 0x03, 0x70, 0xC6, 0x00, 0x06, 0x7C,
                                          0x00, 0xFF, 0x1F, 0xD8, 0x13, 0x03};
  const auto v2 = parse_uclogic_params(s200, 2);
  EXPECT_EQ(v2.x_max, 50800);
  EXPECT_EQ(v2.y_max, 31750);
  EXPECT_EQ(v2.pressure_max, 8191U);
  EXPECT_EQ(v2.resolution_lpi, 5080U); // 10 x 6.25 inches
  const std::vector<std::uint8_t> s100 = {0x0E, 0x03, 0x40, 0x9C, 0xA8, 0x61, 0x03,
                                          0x00, 0xFF, 0x07, 0xA0, 0x0F, 0x08, 0x00};
  const auto v1 = parse_uclogic_params(s100, 1);
  EXPECT_EQ(v1.x_max, 40000);
  EXPECT_EQ(v1.y_max, 25000);
  EXPECT_EQ(v1.pressure_max, 2047U);
  EXPECT_EQ(v1.resolution_lpi, 4000U);
  const auto layout = uclogic_pen_layout(v2);
  EXPECT_DOUBLE_EQ(layout.x_resolution, 200.0);
  EXPECT_THROW((void)parse_uclogic_params(std::vector<std::uint8_t>{0x04, 0x03, 0, 0}, 2),
               std::invalid_argument);
  std::vector<std::uint8_t> zero(s200);
  std::fill(zero.begin() + 2, zero.end(), 0);
  EXPECT_THROW((void)parse_uclogic_params(zero, 2), std::invalid_argument);
}

} // namespace
} // namespace penshape::drivers
