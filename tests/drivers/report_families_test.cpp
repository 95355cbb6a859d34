// Every report family decodes reports built by hand from the layout OpenTabletDriver's parsers
// document (byte positions and flag bits written out here, not taken from families.tsv); every
// layout round-trips through the pen-report encoder; reports of the wrong length are junk.
#include "penshape/drivers/report_families.hpp"

#include <gtest/gtest.h>

#include <random>

#include "penshape/drivers/device_profile.hpp"
#include "penshape/drivers/pen_encoder.hpp"

namespace penshape::drivers {
namespace {

using Bytes = std::vector<std::uint8_t>;

// A decoder for one family with generous maxima (the row's maxima only scale, never mask).
PenDecoder decoder_for(const std::string& family) {
  const ReportFamily* f = find_family(family);
  if (f == nullptr) throw std::invalid_argument("no family " + family);
  TabletSpec spec;
  spec.x_max = 200000;
  spec.y_max = 200000;
  spec.pressure_max = 16383;
  return PenDecoder(family_layouts(*f, spec));
}

struct Expect {
  std::int32_t x = 0x1234, y = 0x0567;
  std::uint32_t pressure = 0x1000;
  bool tip = true, in_range = true;
  std::uint32_t buttons = 0;
  std::int16_t tilt_x = 0, tilt_y = 0;
};

void expect_pen(const std::string& family, const Bytes& report, const Expect& e) {
  SCOPED_TRACE(family);
  PenSample s;
  ASSERT_EQ(decoder_for(family).decode(report, 1, s), DecodeStatus::kPen);
  EXPECT_EQ(s.x, e.x);
  EXPECT_EQ(s.y, e.y);
  EXPECT_EQ(s.pressure, e.pressure);
  EXPECT_EQ(s.tip, e.tip);
  EXPECT_EQ(s.in_range, e.in_range);
  EXPECT_EQ(s.buttons, e.buttons);
  EXPECT_EQ(s.tilt_x, e.tilt_x);
  EXPECT_EQ(s.tilt_y, e.tilt_y);
}

DecodeStatus status(const std::string& family, const Bytes& report) {
  PenSample s;
  return decoder_for(family).decode(report, 1, s);
}

// X 0x1234 and Y 0x0567 little-endian, pressure 0x1000: the words most families share.
const Bytes kXyp = {0x34, 0x12, 0x67, 0x05, 0x00, 0x10};

Bytes cat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

TEST(ReportFamilies, XpPen) {
  // Byte 1: 0xA0 | tip | side switches << 1 | eraser << 3; signed tilt bytes 8, 9.
  expect_pen("xppen", cat({{0x02, 0xA3}, kXyp, {0xFB, 0x07}}),
             {.buttons = kBarrel1, .tilt_x = -5, .tilt_y = 7});
  expect_pen("xppen", cat({{0x02, 0xA9}, kXyp, {0, 0}}), {.buttons = kEraser});
  // 12 bytes: the third coordinate bytes 10 and 11.
  expect_pen("xppen", cat({{0x02, 0xA1}, kXyp, {0, 0, 0x01, 0x02}}),
             {.x = 0x011234, .y = 0x020567});
  expect_pen("xppen", cat({{0x02, 0xC0}, Bytes(8, 0)}),
             {.x = 0, .y = 0, .pressure = 0, .tip = false, .in_range = false});
  EXPECT_EQ(status("xppen", cat({{0x02, 0xF0}, Bytes(8, 0)})), DecodeStatus::kOther);
  // 8-byte reports (no tilt), whatever their report ID.
  expect_pen("xppen", cat({{0x07, 0xA1}, kXyp}), {});
}

TEST(ReportFamilies, XpPenGen2AndOffsetPressure) {
  // Gen2: 24-bit X/Y, pressure bits 0-12 in the word at 6 and bit 13 in byte 13's bit 0.
  expect_pen("xppen-gen2", cat({{0x02, 0xA1}, kXyp, {0xFB, 0x07, 0x01, 0x02, 0x00, 0x01}}),
             {.x = 0x011234, .y = 0x020567, .pressure = 0x3000, .tilt_x = -5, .tilt_y = 7});
  EXPECT_EQ(status("xppen-gen2", cat({{0x02, 0xB0}, Bytes(12, 0)})), DecodeStatus::kOther);
  // Offset pressure: only the low 13 bits of the word are pressure.
  expect_pen("xppen-offset-pressure", {0x02, 0xA1, 0x34, 0x12, 0x67, 0x05, 0xFF, 0xFF, 0x00, 0x00},
             {.pressure = 0x1FFF});
  // Offset aux: bit 5 marks pad frames; 0x80|tip is the pen, 0xC0 out of range.
  expect_pen("xppen-offset-aux", cat({{0x07, 0x81}, kXyp}), {});
  EXPECT_EQ(status("xppen-offset-aux", cat({{0x07, 0xE0}, kXyp})), DecodeStatus::kOther);
  expect_pen("xppen-offset-aux", cat({{0x07, 0xC0}, Bytes(6, 0)}),
             {.x = 0, .y = 0, .pressure = 0, .tip = false, .in_range = false});
}

TEST(ReportFamilies, UcLogicAndGiano) {
  // Report 8: bit 7 in range; third coordinate bytes 8, 9; tilt 10, 11.
  const Bytes v2 = cat({{0x08, 0x83}, kXyp, {0x01, 0x02, 0xFB, 0x07}});
  const Expect e{.x = 0x011234, .y = 0x020567, .buttons = kBarrel1, .tilt_x = -5, .tilt_y = 7};
  for (const char* f : {"uclogic", "uclogic-tilt", "uclogic-v2"}) expect_pen(f, v2, e);
  EXPECT_EQ(status("uclogic", cat({{0x08, 0xE0}, Bytes(10, 0)})), DecodeStatus::kOther);
  EXPECT_EQ(status("uclogic", cat({{0x08, 0xF0}, Bytes(10, 0)})), DecodeStatus::kOther);
  // v1 report 7 (8 bytes): bit 6 set when out of range.
  expect_pen("uclogic", cat({{0x07, 0x81}, kXyp}), {});
  expect_pen("uclogic", cat({{0x07, 0xC0}, Bytes(6, 0)}),
             {.x = 0, .y = 0, .pressure = 0, .tip = false, .in_range = false});
  // Giano: only bit 0 of bytes 8/9 extends X/Y; three barrel buttons; tilt sign flipped.
  expect_pen("huion-giano", cat({{0x08, 0x89}, kXyp, {0x01, 0x03, 0xFB, 0x07}}),
             {.x = 0x011234, .y = 0x010567, .buttons = kBarrel3, .tilt_x = 5, .tilt_y = -7});
  EXPECT_EQ(status("huion-giano", cat({{0x08, 0xF1}, Bytes(10, 0)})), DecodeStatus::kOther);
  EXPECT_EQ(status("huion-giano", cat({{0x08, 0xE0}, Bytes(10, 0)})), DecodeStatus::kOther);
}

TEST(ReportFamilies, Veikk) {
  // Byte 1 0x41 pen; byte 2 0xA0|tip|buttons; X at 3-5, Y at 6-8 (24-bit), pressure at 9.
  const Bytes xy24 = {0x34, 0x12, 0x01, 0x67, 0x05, 0x02, 0x00, 0x10, 0x00, 0x00};
  expect_pen("veikk", cat({{0x09, 0x41, 0xA5}, xy24}),
             {.x = 0x011234, .y = 0x020567, .buttons = kBarrel2});
  EXPECT_EQ(status("veikk", cat({{0x09, 0x43, 0xA1}, xy24})), DecodeStatus::kOther); // touchpad
  expect_pen("veikk-tilt",
             {0x09, 0x41, 0xA1, 0x34, 0x12, 0x01, 0x67, 0x05, 0x02, 0x00, 0x10, 0xFB, 0x07},
             {.x = 0x011234, .y = 0x020567, .tilt_x = -5, .tilt_y = 7});
  expect_pen("veikk-tilt", cat({{0x09, 0x41, 0xC0}, Bytes(10, 0)}),
             {.x = 0, .y = 0, .pressure = 0, .tip = false, .in_range = false});
  // v1 and A15: 16-bit X at 3, Y at 5, pressure at 7.
  expect_pen("veikk-v1", cat({{0x09, 0x41, 0xA9}, kXyp}), {.buttons = kBarrel3});
  EXPECT_EQ(status("veikk-v1", {0x09, 0x41, 0xA9, 0x34, 0x12, 0x67, 0x05, 0x00}),
            DecodeStatus::kJunk); // 8 bytes: the pressure word is cut
  expect_pen("veikk-a15", cat({{0x09, 0x41, 0xA1}, kXyp}), {});
  EXPECT_EQ(status("veikk-a15", cat({{0x09, 0x43, 0xA1}, kXyp})), DecodeStatus::kOther);
}

TEST(ReportFamilies, AcepenGeniusXenceLabsXenxLifetec) {
  expect_pen("acepen", cat({{0x02, 0x41, 0xA3}, kXyp, {0xFB, 0x07}}),
             {.buttons = kBarrel1, .tilt_x = -5, .tilt_y = 7});
  EXPECT_EQ(status("acepen", cat({{0x02, 0x42, 0xA1}, kXyp, {0, 0}})), DecodeStatus::kOther);
  // Genius: report 0x10, tip from pressure; v2: report 2, X at 1, Y at 3, flags at 5.
  expect_pen("genius", cat({{0x10, 0x02}, kXyp}), {.buttons = kBarrel1});
  expect_pen("genius-v2", {0x02, 0x34, 0x12, 0x67, 0x05, 0x0C, 0x00, 0x10}, {.buttons = kBarrel1});
  // XenceLabs: bit 5 pen, bit 6 eraser, tip from pressure.
  expect_pen("xencelabs", cat({{0x02, 0x61}, kXyp, {0xFB, 0x07}}),
             {.buttons = kEraser, .tilt_x = -5, .tilt_y = 7});
  EXPECT_EQ(status("xencelabs", cat({{0x02, 0xF0}, kXyp, {0, 0}})), DecodeStatus::kOther);
  // XENX: report 1; byte 1 zero when the pen leaves.
  expect_pen("xenx", cat({{0x01, 0x41}, kXyp}), {.buttons = kEraser});
  expect_pen("xenx", cat({{0x01, 0x00}, Bytes(6, 0)}),
             {.x = 0, .y = 0, .pressure = 0, .tip = false, .in_range = false});
  expect_pen("lifetec", {0x02, 0x34, 0x12, 0x67, 0x05, 0x10, 0x00, 0x10}, {.buttons = kBarrel2});
  expect_pen("tablet", cat({{0x07, 0x02}, kXyp}), {.buttons = kBarrel1});
  expect_pen("tablet-skip1", cat({{0x07, 0x00, 0x02}, kXyp}), {.buttons = kBarrel1});
}

TEST(ReportFamilies, WacomClassic) {
  // Graphire: bit 7 range, bit 5 eraser, bit 6 the mouse; 10-bit pressure in bytes 6-7.
  expect_pen("wacom-graphire", {0x02, 0xA1, 0x34, 0x12, 0x67, 0x05, 0xFF, 0x03},
             {.pressure = 1023, .buttons = kEraser});
  EXPECT_EQ(status("wacom-graphire", {0x02, 0xC1, 0, 0, 0, 0, 0, 0}), DecodeStatus::kOther);
  // Bamboo (OTD's Intuos): bit 6 proximity, bit 3 eraser; and the Wacom driver's copy one byte
  // later, whose byte 1 is the report ID.
  expect_pen("wacom-bamboo", cat({{0x02, 0x61}, kXyp, {0x00}}), {});
  expect_pen("wacom-bamboo-skip1", cat({{0x05, 0x02, 0x69}, kXyp, {0x00}}), {.buttons = kEraser});
  EXPECT_EQ(status("wacom-bamboo-skip1", cat({{0x05, 0x03, 0x61}, kXyp, {0x00}})),
            DecodeStatus::kOther);
  // Intuos V1 packet as report 0x10: X = 0x1234 << 1 | 1, pressure (0x80 << 3) | (3 << 1) | 1,
  // tilt X ((0x20 << 1) | 1) - 64, tilt Y 0x50 - 64.
  for (const char* f : {"wacom-intuos", "wacom-intuos3", "wacom-intuos4", "wacom-cintiq"}) {
    expect_pen(f, {0x10, 0xA3, 0x12, 0x34, 0x05, 0x67, 0x80, 0xE0, 0xD0, 0x02},
               {.x = 0x2469,
                .y = 0x0ACE,
                .pressure = 1031,
                .buttons = kBarrel1,
                .tilt_x = 1,
                .tilt_y = 16});
  }
  // Leaving packet (tilt bytes 0: -64 degrees, the bottom of the 0..127 scale).
  expect_pen("wacom-intuos-skip1", {0x05, 0x02, 0x80, 0, 0, 0, 0, 0, 0, 0, 0},
             {.x = 0,
              .y = 0,
              .pressure = 0,
              .tip = false,
              .in_range = false,
              .tilt_x = -64,
              .tilt_y = -64});
}

TEST(ReportFamilies, WacomModern) {
  // Intuos V2 report 0x10: 24-bit X at 2, Y at 5, pressure at 8, tilt 10/11, bit 5 range.
  Bytes v2 = {0x10, 0x23, 0x34, 0x12, 0x01, 0x67, 0x05, 0x02, 0x00, 0x10, 0xFB, 0x07};
  v2.resize(17, 0);
  expect_pen("wacom-intuos-v2", v2,
             {.x = 0x011234, .y = 0x020567, .buttons = kBarrel1, .tilt_x = -5, .tilt_y = 7});
  Bytes v2e = {0x10, 0x10};
  v2e.resize(17, 0);
  expect_pen("wacom-intuos-v2", v2e,
             {.x = 0, .y = 0, .pressure = 0, .tip = false, .in_range = false, .buttons = kEraser});
  // Intuos V3 report 0x1F (byte 1 == 1): flags at 2 (bit 6 range, bit 5 eraser), X at 3.
  const Bytes v3 = {0x1F, 0x01, 0x42, 0x34, 0x12, 0x67, 0x05,
                    0x00, 0x10, 0xFB, 0x00, 0x07, 0x00, 0x00};
  expect_pen("wacom-intuos-v3", v3, {.buttons = kBarrel1, .tilt_x = -5, .tilt_y = 7});
  Bytes v3e = {0x1E, 0x00, 0x60, 0x34, 0x12, 0x01, 0x67, 0x05,
               0x02, 0x00, 0x10, 0xFB, 0xFF, 0x07, 0x00};
  v3e.resize(20, 0);
  expect_pen("wacom-intuos-v3", v3e,
             {.x = 0x011234, .y = 0x020567, .buttons = kEraser, .tilt_x = -5, .tilt_y = 7});
  // Bamboo Pad: report 0x10, byte 1 == 1, flags at 2 (bit 1 button, bit 3 eraser).
  expect_pen("wacom-bamboo-pad", cat({{0x10, 0x01, 0x0A}, kXyp}), {.buttons = kBarrel1 | kEraser});
  // PTU: bit 5 range, bit 2 eraser, buttons bits 1 and 4.
  expect_pen("wacom-ptu", cat({{0x02, 0x30}, kXyp}), {.buttons = kBarrel2});
}

// Every layout of every family: encode a sample, decode it back; shorter reports are junk and
// random bytes of every length never crash.
TEST(ReportFamilies, EveryLayoutRoundTripsAndRejectsShortReports) {
  std::mt19937 rng(7);
  std::size_t layouts = 0;
  for (const auto& f : builtin_families()) {
    SCOPED_TRACE(f.name);
    TabletSpec spec;
    spec.x_max = 30000;
    spec.y_max = 20000;
    spec.pressure_max = 4095;
    const auto all = family_layouts(f, spec);
    for (std::size_t i = 0; i < all.size(); ++i) {
      const PenLayout& l = all[i];
      ++layouts;
      PenSample s;
      s.x = 12345;
      s.y = 6789;
      s.pressure = l.pressure.total_bits() >= 12 ? 4000U : 1000U;
      s.tip = true;
      s.in_range = true;
      if (l.barrel1.present()) s.buttons |= kBarrel1;
      if (l.tilt_x.present()) {
        s.tilt_x = -20;
        s.tilt_y = 30;
      }
      // A decoder of this layout alone: the family's other layouts may share its report shape.
      const PenDecoder alone({l});
      Bytes r = encode_pen_report(l, s);
      PenSample back;
      if (alone.decode(r, 5, back) != DecodeStatus::kPen && l.in_range.present()) {
        // A layout only for the pen leaving (XENX): it carries an out-of-range sample.
        s.tip = false;
        s.in_range = false;
        s.pressure = 0;
        s.buttons = 0;
        r = encode_pen_report(l, s);
      }
      ASSERT_EQ(alone.decode(r, 5, back), DecodeStatus::kPen) << "layout " << i;
      EXPECT_EQ(back.x, s.x);
      EXPECT_EQ(back.y, s.y);
      EXPECT_EQ(back.pressure, s.pressure);
      EXPECT_EQ(back.tip, s.tip);
      EXPECT_EQ(back.in_range, s.in_range);
      EXPECT_EQ(back.buttons, s.buttons);
      EXPECT_EQ(back.tilt_x, s.tilt_x);
      EXPECT_EQ(back.tilt_y, s.tilt_y);
      PenSample junk;
      EXPECT_EQ(alone.decode(Bytes(r.begin(), r.end() - 1), 5, junk), DecodeStatus::kJunk);
    }
    const PenDecoder d(all);
    for (std::size_t n = 0; n < 80; ++n) {
      Bytes r(n % 40);
      for (auto& b : r) b = static_cast<std::uint8_t>(rng());
      PenSample s;
      (void)d.decode(r, 0, s); // any status; must not crash or read out of bounds
    }
  }
  EXPECT_GE(layouts, 40U);
}

TEST(ReportFamilies, BadFamilyLinesNameTheirLine) {
  EXPECT_THROW((void)parse_report_families("f\thid\tid=02 len=8 x=2:16\n"), FamilyTableError);
  try {
    (void)parse_report_families("# c\nf\tvendor\tid=02 len=8 x=2:16 y=4:40\n");
    FAIL();
  } catch (const FamilyTableError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("y=4:40"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)parse_report_families("f\tvendor\t@nothing\n"), FamilyTableError);
  EXPECT_THROW((void)parse_report_families("f\tnope\t-\n"), FamilyTableError);
  EXPECT_THROW((void)parse_report_families("f\tvendor\tid=02 len=8 x=2:16 y=4:16 match=1&0f==f0\n"),
               FamilyTableError);
  const auto ok = parse_report_families(
      "a\tvendor\tid=02 len=8 x=2:16 y=4:16 p=6:8,7.0:2 tip=1.0\nb\tvendor\t@a shift=1\n");
  ASSERT_EQ(ok.size(), 2U);
  EXPECT_EQ(ok[1].layouts[0].x.bit_offset, 24U);
  EXPECT_EQ(ok[1].layouts[0].pressure.high_bit_offset, 64U);
  EXPECT_EQ(ok[1].layouts[0].match_byte, 1U); // the report ID moved to byte 1
  EXPECT_EQ(ok[1].layouts[0].min_report_bytes, 9U);
}

} // namespace
} // namespace penshape::drivers
