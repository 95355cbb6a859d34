// Vendor report formats on hand-built reports whose expected values follow from the formats'
// documentation in vendor_protocols.hpp (byte positions and flag bits), not from our decoder.
#include "penshape/drivers/vendor_protocols.hpp"

#include <gtest/gtest.h>

#include "penshape/drivers/device_profile.hpp"

namespace penshape::drivers {
namespace {

using Bytes = std::vector<std::uint8_t>;

DecodeStatus decode(const DeviceProfile& p, const Bytes& r, PenSample& s) {
  return p.decoder.decode(r, 42, s);
}

TEST(VendorProtocols, WacomBambooAfterModeSwitch) {
  // One by Wacom S (CTL-472): vendor-page descriptor only, so the Bamboo layout and the
  // mode-switch feature report 02 02.
  const DeviceProfile p = build_profile({Bus::kUsb, 0x056a, 0x037a, ""}, {});
  EXPECT_EQ(p.protocol, Protocol::kWacomBamboo);
  ASSERT_EQ(p.init.size(), 1U);
  EXPECT_EQ(p.init[0].bytes, (Bytes{0x02, 0x02}));
  EXPECT_EQ(p.info.x_max, 15200);
  EXPECT_EQ(p.info.pressure_max, 2047U);
  PenSample s;
  // range|prox|ready|tip, x 1000, y 2000, pressure 500, distance 0.
  ASSERT_EQ(decode(p, {0x02, 0xE1, 0xE8, 0x03, 0xD0, 0x07, 0xF4, 0x01, 0x00, 0x00}, s),
            DecodeStatus::kPen);
  EXPECT_EQ(s.x, 1000);
  EXPECT_EQ(s.y, 2000);
  EXPECT_EQ(s.pressure, 500U);
  EXPECT_TRUE(s.tip);
  EXPECT_TRUE(s.in_range);
  EXPECT_EQ(s.time_us, 42);
  // Eraser end hovering with the lower side switch.
  ASSERT_EQ(decode(p, {0x02, 0xEA, 0, 0, 0, 0, 0, 0, 0}, s), DecodeStatus::kPen);
  EXPECT_EQ(s.buttons, static_cast<std::uint32_t>(kEraser | kBarrel1));
  EXPECT_FALSE(s.tip);
  // Leaving: neither range nor proximity.
  ASSERT_EQ(decode(p, {0x02, 0x00, 0, 0, 0, 0, 0, 0, 0}, s), DecodeStatus::kPen);
  EXPECT_FALSE(s.in_range);
  EXPECT_EQ(decode(p, {0x02, 0xE1, 0, 0}, s), DecodeStatus::kJunk); // too short
}

TEST(VendorProtocols, WacomIntuosScatteredFields) {
  // Intuos Pro PTH-851: vendor-page descriptors only.
  const DeviceProfile p = build_profile({Bus::kUsb, 0x056a, 0x0317, ""}, {});
  EXPECT_EQ(p.protocol, Protocol::kWacomIntuos);
  EXPECT_EQ(p.info.x_max, 65024);
  EXPECT_EQ(p.info.pressure_max, 2047U);
  PenSample s;
  // General pen packet 0xA1: X = 0x1234 << 1 | 1 (byte 9 bit 1), Y = 0x0567 << 1 | 0,
  // pressure = 0x80 << 3 | 0b11 << 1 | 1 = 1031, tilt X = (0x20 << 1 | 1) - 64 = 1,
  // tilt Y = 0x50 - 64 = 16.
  ASSERT_EQ(decode(p, {0x02, 0xA1, 0x12, 0x34, 0x05, 0x67, 0x80, 0xE0, 0xD0, 0x02}, s),
            DecodeStatus::kPen);
  EXPECT_EQ(s.x, 0x2469);
  EXPECT_EQ(s.y, 0x0ACE);
  EXPECT_EQ(s.pressure, 1031U);
  EXPECT_EQ(s.tilt_x, 1);
  EXPECT_EQ(s.tilt_y, 16);
  EXPECT_TRUE(s.tip);
  EXPECT_TRUE(s.in_range);
  // Side switch 2, hovering with pressure 5 (not above the threshold of 10): no tip.
  ASSERT_EQ(decode(p, {0x02, 0xA5, 0, 0, 0, 0, 0x00, 0x80, 0x00, 0x00}, s), DecodeStatus::kPen);
  EXPECT_EQ(s.pressure, 5U);
  EXPECT_FALSE(s.tip);
  EXPECT_EQ(s.buttons, static_cast<std::uint32_t>(kBarrel2));
  // Leaving proximity, then a tool announcement (no position): not a pen sample.
  ASSERT_EQ(decode(p, {0x02, 0x80, 0, 0, 0, 0, 0, 0, 0, 0}, s), DecodeStatus::kPen);
  EXPECT_FALSE(s.in_range);
  EXPECT_EQ(decode(p, {0x02, 0xC2, 0x08, 0x02, 0, 0, 0, 0, 0, 0}, s), DecodeStatus::kOther);
}

TEST(VendorProtocols, GraphireMouseIsNotThePen) {
  const DeviceProfile p = build_profile({Bus::kUsb, 0x056a, 0x0061, ""}, {});
  PenSample s;
  // Tool 2 (bit 6): the Graphire mouse.
  EXPECT_EQ(decode(p, {0x02, 0xC0, 1, 0, 1, 0, 0, 0}, s), DecodeStatus::kOther);
  // Pen, tip, pressure 0x1FF split over byte 6 and two bits of byte 7.
  ASSERT_EQ(decode(p, {0x02, 0x81, 0x10, 0x00, 0x20, 0x00, 0xFF, 0x01}, s), DecodeStatus::kPen);
  EXPECT_EQ(s.pressure, 0x1FFU);
  EXPECT_EQ(s.x, 0x10);
}

TEST(VendorProtocols, UcLogicV2SplitCoordinatesAndFrames) {
  const Bytes s200 = {0x13, 0x03, 0x70, 0xC6, 0x00, 0x06, 0x7C, 0x00, 0xFF, 0x1F, 0xD8, 0x13};
  // A big UC-Logic tablet: X beyond 16 bits (Kamvas 24 class, 105370 units).
  Bytes big = s200;
  big[2] = 0x9A;
  big[3] = 0x9B;
  big[4] = 0x01; // 0x019B9A = 105370
  const DeviceProfile p = build_profile({Bus::kUsb, 0x256c, 0x006d, ""}, {}, {{200, big}});
  EXPECT_EQ(p.info.x_max, 105370);
  PenSample s;
  // x = 0x019000 (low 16 bits at bytes 2-3, high byte at 8), y = 0x1234, tilt -5/+7.
  ASSERT_EQ(decode(p, {0x08, 0x81, 0x00, 0x90, 0x34, 0x12, 0x00, 0x10, 0x01, 0x00, 0xFB, 0x07}, s),
            DecodeStatus::kPen);
  EXPECT_EQ(s.x, 0x019000);
  EXPECT_EQ(s.y, 0x1234);
  EXPECT_EQ(s.pressure, 0x1000U);
  EXPECT_EQ(s.tilt_x, -5);
  EXPECT_EQ(s.tilt_y, 7);
  EXPECT_TRUE(s.tip);
  // Pad buttons (0xE0) and dials (0xF0) share report 8 and are not the pen.
  EXPECT_EQ(decode(p, {0x08, 0xE0, 0x01, 0x01, 0, 0, 0, 0, 0, 0, 0, 0}, s), DecodeStatus::kOther);
  EXPECT_EQ(decode(p, {0x08, 0xF0, 0x01, 0x01, 0, 0, 0, 0, 0, 0, 0, 0}, s), DecodeStatus::kOther);
}

TEST(VendorProtocols, XpPenVendorModeWhenTheDescriptorHasNoPen) {
  // No descriptor: the XP-Pen vendor report, enabled by output report 02 B0 04.
  const DeviceProfile p = build_profile({Bus::kUsb, 0x28bd, 0x0907, ""}, {});
  EXPECT_EQ(p.protocol, Protocol::kXpPen);
  ASSERT_EQ(p.init.size(), 1U);
  EXPECT_EQ(p.init[0].kind, InitStep::Kind::kOutputReport);
  EXPECT_EQ(p.init[0].bytes, (Bytes{0x02, 0xB0, 0x04}));
  PenSample s;
  ASSERT_EQ(decode(p, {0x02, 0xA1, 0x10, 0x27, 0x20, 0x4E, 0xFF, 0x0F, 0x03, 0xFD}, s),
            DecodeStatus::kPen);
  EXPECT_EQ(s.x, 10000);
  EXPECT_EQ(s.y, 20000);
  EXPECT_EQ(s.pressure, 4095U);
  EXPECT_EQ(s.tilt_x, 3);
  EXPECT_EQ(s.tilt_y, -3);
  EXPECT_TRUE(s.in_range);
  ASSERT_EQ(decode(p, {0x02, 0xC0, 0, 0, 0, 0, 0, 0, 0, 0}, s), DecodeStatus::kPen);
  EXPECT_FALSE(s.in_range);
  EXPECT_EQ(decode(p, {0x02, 0xF0, 0x01, 0, 0, 0, 0, 0, 0, 0}, s), DecodeStatus::kOther);
}

TEST(VendorProtocols, DescriptorRewrittenByTheKernelWins) {
  // HS610 with hid-uclogic bound: the sysfs descriptor already describes report 8 (24-bit X);
  // the vendor layout must not be applied on top.
  const Bytes s200 = {0x13, 0x03, 0x70, 0xC6, 0x00, 0x06, 0x7C, 0x00, 0xFF, 0x1F, 0xD8, 0x13};
  const Bytes rewritten = {
      0x05, 0x0d, 0x09, 0x02, 0xa1, 0x01, 0x85, 0x08, 0x09, 0x20, 0xa0, 0x14, 0x25, 0x01, 0x75,
      0x01, 0x09, 0x42, 0x09, 0x44, 0x09, 0x46, 0x95, 0x03, 0x81, 0x02, 0x95, 0x03, 0x81, 0x03,
      0x09, 0x32, 0x95, 0x01, 0x81, 0x02, 0x95, 0x01, 0x81, 0x03, 0x05, 0x01, 0x75, 0x18, 0x09,
      0x30, 0x27, 0x70, 0xc6, 0x00, 0x00, 0x81, 0x02, 0x09, 0x31, 0x27, 0x06, 0x7c, 0x00, 0x00,
      0x81, 0x02, 0x05, 0x0d, 0x09, 0x30, 0x75, 0x10, 0x26, 0xff, 0x1f, 0x81, 0x02, 0xc0, 0xc0};
  const DeviceProfile p = build_profile({Bus::kUsb, 0x256c, 0x006d, ""}, rewritten, {{200, s200}});
  ASSERT_EQ(p.decoder.layouts().size(), 1U);
  EXPECT_EQ(p.decoder.layouts()[0].origin, "hid");
  EXPECT_EQ(p.info.x_max, 50800);
  PenSample s;
  // Contiguous 24-bit X as the kernel rewrote it: 0x00C000.
  ASSERT_EQ(decode(p, {0x08, 0x81, 0x00, 0xC0, 0x00, 0x10, 0x00, 0x00, 0x20, 0x00}, s),
            DecodeStatus::kPen);
  EXPECT_EQ(s.x, 0xC000);
  EXPECT_EQ(s.y, 0x10);
  EXPECT_EQ(s.pressure, 0x20U);
}

} // namespace
} // namespace penshape::drivers
