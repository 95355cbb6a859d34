// The HID descriptor parser: the item grammar on hand-built descriptors (checked against the
// HID 1.11 rules by hand), then every real descriptor in ../shared/data/hid.
#include "penshape/drivers/hid_descriptor.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace penshape::drivers {
namespace {

using Bytes = std::vector<std::uint8_t>;

// A pen report, report ID 2: tip, barrel, 6 pad bits, X 16 bits, Y 16 bits, pressure 12 bits +
// 4 pad bits; physical X 0..2000 with unit inch exponent -3 (a 2-inch, 50.8 mm axis).
const Bytes kPen = {0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01, // Digitizer / Pen, Application
                    0x85, 0x02, 0x09, 0x20, 0xA1, 0x00, // Report ID 2, Stylus, Physical
                    0x09, 0x42, 0x09, 0x44, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01,
                    0x95, 0x02, 0x81, 0x02, 0x95, 0x06, 0x81, 0x03,       // 6 bits padding
                    0x05, 0x01, 0x09, 0x30, 0x09, 0x31,                   // X, Y
                    0xA4,                                                 // Push
                    0x65, 0x13, 0x55, 0x0D,                               // unit inch, exponent -3
                    0x35, 0x00, 0x46, 0xD0, 0x07,                         // physical 0..2000
                    0x26, 0x10, 0x27, 0x75, 0x10, 0x95, 0x02, 0x81, 0x02, // logical 0..10000
                    0xB4,                                                 // Pop
                    0x05, 0x0D, 0x09, 0x30, 0x26, 0xFF, 0x0F, 0x75, 0x0C, 0x95,
                    0x01, 0x81, 0x02, 0x75, 0x04, 0x81, 0x03, 0xC0, 0xC0};

TEST(HidDescriptor, PenReportLayout) {
  const auto d = parse_report_descriptor(kPen);
  EXPECT_TRUE(d.uses_report_ids);
  ASSERT_EQ(d.applications.size(), 1U);
  EXPECT_EQ(d.applications[0], make_usage(0x0D, 0x02));
  const ReportLayout* r = d.find(ReportType::kInput, 2);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->size_bits, 8U + 2 + 6 + 32 + 12 + 4);
  ASSERT_EQ(r->fields.size(), 7U); // tip, barrel, pad, X, Y, pressure, pad
  EXPECT_EQ(r->fields[0].usage, make_usage(0x0D, 0x42));
  EXPECT_EQ(r->fields[0].bit_offset, 8U);
  EXPECT_EQ(r->fields[1].usage, make_usage(0x0D, 0x44));
  EXPECT_EQ(r->fields[1].bit_offset, 9U);
  EXPECT_TRUE(r->fields[2].is_constant());
  const ReportField& x = r->fields[3];
  EXPECT_EQ(x.usage, make_usage(0x01, 0x30));
  EXPECT_EQ(x.bit_offset, 16U);
  EXPECT_EQ(x.logical_maximum, 10000);
  EXPECT_EQ(x.physical_maximum, 2000);
  EXPECT_EQ(x.unit, 0x13U);
  EXPECT_EQ(x.unit_exponent, -3);
  EXPECT_EQ(x.collection, make_usage(0x0D, 0x20));
  EXPECT_EQ(x.application, make_usage(0x0D, 0x02));
  const ReportField& y = r->fields[4];
  EXPECT_EQ(y.usage, make_usage(0x01, 0x31));
  EXPECT_EQ(y.bit_offset, 32U);
  // After Pop the unit and physical range are gone again.
  const ReportField& p = r->fields[5];
  EXPECT_EQ(p.usage, make_usage(0x0D, 0x30));
  EXPECT_EQ(p.bit_offset, 48U);
  EXPECT_EQ(p.bit_size, 12U);
  EXPECT_EQ(p.logical_maximum, 4095);
  EXPECT_EQ(p.unit, 0U);
  EXPECT_EQ(p.physical_maximum, 4095); // physical 0/0 means "same as logical"
}

TEST(HidDescriptor, UsageRangesArraysAndExtendedUsages) {
  const Bytes d = {0x05, 0x09, 0xA1, 0x01,                         // Button page, application
                   0x19, 0x01, 0x29, 0x03, 0x15, 0x00, 0x25, 0x01, // Buttons 1..3
                   0x75, 0x01, 0x95, 0x03, 0x81, 0x02,             // 3 variable bits
                   0x0B, 0x38, 0x02, 0x0C, 0x00,                   // extended usage Consumer/AC Pan
                   0x75, 0x05, 0x95, 0x01, 0x81, 0x06,             // 5-bit relative
                   0x05, 0x07, 0x19, 0x00, 0x2A, 0xFF, 0x00,       // keyboard array 0..255
                   0x26, 0xFF, 0x00, 0x75, 0x08, 0x95, 0x06, 0x81, 0x00, 0xC0};
  const auto p = parse_report_descriptor(d);
  EXPECT_FALSE(p.uses_report_ids);
  const auto* r = p.find(ReportType::kInput, 0);
  ASSERT_NE(r, nullptr);
  ASSERT_EQ(r->fields.size(), 5U);
  for (unsigned i = 0; i < 3; ++i) {
    EXPECT_EQ(r->fields[i].usage, make_usage(0x09, static_cast<std::uint16_t>(i + 1)));
    EXPECT_EQ(r->fields[i].bit_offset, i);
  }
  EXPECT_EQ(r->fields[3].usage, make_usage(0x0C, 0x0238));
  EXPECT_TRUE(r->fields[3].is_relative());
  EXPECT_FALSE(r->fields[4].is_variable());
  EXPECT_EQ(r->fields[4].count, 6U);
  EXPECT_EQ(r->fields[4].usage_maximum, make_usage(0x07, 0xFF));
  EXPECT_EQ(r->fields[4].logical_maximum, 255);
  EXPECT_EQ(r->size_bits, 8U + 48U);
}

TEST(HidDescriptor, OneByteMaximumAfterNonNegativeMinimumIsUnsigned) {
  // 25 FF after 15 00: devices mean 255 (the spec would say -1).
  const Bytes d = {0x05, 0x01, 0x09, 0x30, 0x15, 0x00, 0x25,
                   0xFF, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02};
  const auto p = parse_report_descriptor(d);
  EXPECT_EQ(p.reports.at(0).fields.at(0).logical_maximum, 255);
  const Bytes s = {0x05, 0x01, 0x09, 0x30, 0x15, 0x81, 0x25,
                   0x7F, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02};
  const auto q = parse_report_descriptor(s);
  EXPECT_EQ(q.reports.at(0).fields.at(0).logical_minimum, -127);
  EXPECT_TRUE(q.reports.at(0).fields.at(0).is_signed());
}

TEST(HidDescriptor, LongItemsAreSkipped) {
  const Bytes d = {0xFE, 0x02, 0x10, 0xAA, 0xBB, 0x05, 0x01, 0x09,
                   0x30, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02};
  const auto p = parse_report_descriptor(d);
  EXPECT_EQ(p.long_items, 1U);
  EXPECT_EQ(p.reports.at(0).fields.at(0).usage, make_usage(0x01, 0x30));
}

struct BadCase {
  Bytes bytes;
  std::size_t offset;
  const char* mentions;
};

TEST(HidDescriptor, MalformedInputNamesTheByteOffset) {
  const std::vector<BadCase> cases = {
      {{}, 0, "empty"},
      {{0x05, 0x01, 0x26, 0xFF}, 2, "truncated"},
      {{0x05, 0x01, 0xB4}, 2, "pop without push"},
      {{0x05, 0x01, 0xC0}, 2, "end collection"},
      {{0x85, 0x00}, 0, "report ID 0"},
      {{0x95, 0x01, 0x75, 0x08, 0x96, 0x00, 0x20}, 4, "report count"},
      {{0xFE, 0x05, 0x00, 0x01}, 0, "long item"},
      {{0x0C}, 0, "reserved item type"},
      {{0x75, 0x08, 0x95, 0x01, 0x81, 0x02, 0x85, 0x01, 0x81, 0x02}, 8, "report IDs declared"},
  };
  for (const auto& c : cases) {
    try {
      (void)parse_report_descriptor(c.bytes);
      ADD_FAILURE() << "accepted " << c.mentions;
    } catch (const DescriptorError& e) {
      EXPECT_EQ(e.offset(), c.offset) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.mentions), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("byte " + std::to_string(c.offset)), std::string::npos);
    }
  }
  Bytes huge(kMaxDescriptorBytes + 1, 0x00);
  EXPECT_THROW((void)parse_report_descriptor(huge), DescriptorError);
}

TEST(HidDescriptor, ReportLongerThanTheLimitIsRejected) {
  // 4096 values of 32 bits in one report = 16 KiB; a second item overflows.
  const Bytes d = {0x75, 0x20, 0x96, 0x00, 0x10, 0x81, 0x03, 0x81, 0x03};
  EXPECT_THROW((void)parse_report_descriptor(d), DescriptorError);
}

TEST(HidDescriptor, ExtractBitsAndSignExtend) {
  const Bytes r = {0xAB, 0xCD, 0xEF, 0x12};
  EXPECT_EQ(extract_bits(r, 0, 8), 0xABU);
  EXPECT_EQ(extract_bits(r, 4, 8), 0xDAU);
  EXPECT_EQ(extract_bits(r, 8, 16), 0xEFCDU);
  EXPECT_EQ(extract_bits(r, 0, 32), 0x12EFCDABU);
  EXPECT_EQ(extract_bits(r, 28, 8), 0x1U); // past the end reads as zero
  EXPECT_EQ(extract_bits(r, 100, 8), 0U);
  EXPECT_EQ(sign_extend(0xFF, 8), -1);
  EXPECT_EQ(sign_extend(0x7F, 8), 127);
  EXPECT_EQ(sign_extend(0x800, 12), -2048);
}

} // namespace
} // namespace penshape::drivers
