// The capture file `penshape record` writes (record_command_capture.hpp), checked by reading it
// back with the drivers' hid-recorder parser: header facts from DeviceInfo.hid (and the refusal of
// facts no file can hold), times relative to the first report and never decreasing, and the cut
// that ends a --strokes capture after a given report.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

#include "penshape/drivers/recording.hpp"
#include "record_command_capture.hpp"

namespace penshape::cli {
namespace {

v1::DeviceInfo device_with_hid() {
  v1::DeviceInfo d;
  d.set_id("hidraw7");
  v1::HidFacts* hid = d.mutable_hid();
  hid->set_report_descriptor(std::string("\x05\x0d\x09\x02\xa1\x01\xc0", 7));
  hid->set_name("UGTABLET 10 inch PenTablet");
  hid->set_phys("usb-0000:00:14.0-2/input0");
  hid->set_bus(3);
  hid->set_vendor_id(0x28bd);
  hid->set_product_id(0x0905);
  v1::VendorString* s = hid->add_vendor_strings();
  s->set_index(200);
  s->set_data(std::string("\x06\x03\x41\x00\x42\x00", 6));
  return d;
}

TEST(RecordCapture, HeaderFactsComeFromTheDaemonsDescription) {
  const auto header = capture_header(device_with_hid());
  ASSERT_TRUE(header.has_value());
  EXPECT_EQ(header->descriptor,
            (std::vector<std::uint8_t>{0x05, 0x0d, 0x09, 0x02, 0xa1, 0x01, 0xc0}));
  EXPECT_EQ(header->identity.name, "UGTABLET 10 inch PenTablet");
  EXPECT_EQ(header->phys, "usb-0000:00:14.0-2/input0");
  EXPECT_EQ(header->identity.bus, Bus::kUsb);
  EXPECT_EQ(header->identity.vendor_id, 0x28bd);
  EXPECT_EQ(header->identity.product_id, 0x0905);
  EXPECT_TRUE(header->has_identity);
  ASSERT_EQ(header->vendor_strings.count(200), 1U);
  EXPECT_EQ(header->vendor_strings.at(200),
            (std::vector<std::uint8_t>{0x06, 0x03, 0x41, 0x00, 0x42, 0x00}));
}

TEST(RecordCapture, NoDescriptorMeansNoCapture) {
  v1::DeviceInfo old_daemon; // no hid at all
  old_daemon.set_id("hidraw3");
  EXPECT_FALSE(capture_header(old_daemon).has_value());
  v1::DeviceInfo empty = device_with_hid();
  empty.mutable_hid()->clear_report_descriptor();
  EXPECT_FALSE(capture_header(empty).has_value());
}

TEST(RecordCapture, FactsNoFileCanHoldAreRefusedByName) {
  const auto refused = [](const v1::DeviceInfo& d, const std::string& words) {
    try {
      (void)capture_header(d);
      ADD_FAILURE() << "accepted; expected an error naming " << words;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  v1::DeviceInfo d = device_with_hid();
  d.mutable_hid()->mutable_vendor_strings(0)->set_index(256);
  refused(d, "vendor_strings index 256");
  d = device_with_hid();
  d.mutable_hid()->set_vendor_id(0x10000);
  refused(d, "vendor_id");
  d = device_with_hid();
  d.mutable_hid()->set_bus(70000);
  refused(d, "bus");
  d = device_with_hid();
  d.mutable_hid()->set_report_descriptor(std::string(4097, '\x05'));
  refused(d, "report_descriptor has 4097 bytes");
}

TEST(RecordCapture, ANameCannotBreakTheLineStructure) {
  v1::DeviceInfo d = device_with_hid();
  d.mutable_hid()->set_name("Evil\nE: 0.000000 1 ff");
  std::ostringstream out;
  CaptureWriter writer(out, *capture_header(d), "two\nlines", false);
  writer.write(std::string("\x02\x01", 2), 5);
  const drivers::Recording back = drivers::read_hid_recorder(out.str());
  EXPECT_EQ(back.identity.name, "Evil E: 0.000000 1 ff");
  ASSERT_EQ(back.events.size(), 1U); // only the real report
  EXPECT_EQ(back.events[0].bytes, (std::vector<std::uint8_t>{0x02, 0x01}));
}

TEST(RecordCapture, ReadsBackAsTheDeviceWithTimesFromTheFirstReport) {
  const drivers::Recording header = *capture_header(device_with_hid());
  std::ostringstream out;
  CaptureWriter writer(out, header, "test capture", false);
  // Device clock: starts at 1 s; one step back (a clock adjustment) must not go backwards.
  const std::vector<std::pair<std::int64_t, std::string>> reports{
      {1'000'000, std::string("\x02\x90\x10\x00", 4)},
      {1'007'978, std::string("\x63\x00", 2)},
      {1'007'000, std::string("\x02\x91\x11\x00", 4)},
      {2'500'001, std::string("\x02\x80\x12\x00", 4)},
  };
  for (const auto& [t, bytes] : reports) writer.write(bytes, t);
  EXPECT_EQ(writer.reports(), 4U);
  EXPECT_EQ(writer.bytes_written(), out.str().size());

  const drivers::Recording back = drivers::read_hid_recorder(out.str());
  EXPECT_EQ(back.descriptor, header.descriptor);
  EXPECT_EQ(back.identity.name, header.identity.name);
  EXPECT_EQ(back.phys, header.phys);
  EXPECT_TRUE(back.has_identity);
  EXPECT_EQ(back.identity.vendor_id, 0x28bd);
  EXPECT_EQ(back.vendor_strings, header.vendor_strings);
  ASSERT_EQ(back.events.size(), 4U);
  const std::vector<std::int64_t> want_times{0, 7'978, 7'978, 1'500'001};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(back.events[i].time_us, want_times[i]) << i;
    EXPECT_EQ(std::string(back.events[i].bytes.begin(), back.events[i].bytes.end()),
              reports[i].second)
        << i;
  }
  // hid-recorder's own line order: D:, R:, N:, P:, I:, then the events after a second D:.
  const std::string text = out.str();
  const auto at = [&](const std::string& s) { return text.find(s); };
  EXPECT_LT(at("\nD: 0\nR: 7 05 0d"), at("\nN: UGTABLET"));
  EXPECT_LT(at("\nN: "), at("\nP: "));
  EXPECT_LT(at("\nP: "), at("\nI: 3 28bd 0905\n"));
  EXPECT_LT(at("\nI: "), at("\nD: 0\nE: 0.000000 4 02 90 10 00\n"));
}

TEST(RecordCapture, CutKeepsExactlyTheReportsUpToAGivenTime) {
  std::ostringstream out;
  CaptureWriter writer(out, *capture_header(device_with_hid()), "cut", true);
  for (std::int64_t t = 100; t <= 500; t += 100) {
    writer.write(std::string(1, static_cast<char>(t / 100)), t);
  }
  const auto kept = [&](const CaptureWriter::Cut& cut) {
    return drivers::read_hid_recorder(out.str().substr(0, cut.bytes)).events.size();
  };
  const CaptureWriter::Cut three = writer.cut_through(300);
  EXPECT_EQ(three.reports, 3U);
  EXPECT_EQ(kept(three), 3U);
  EXPECT_EQ(writer.cut_through(350).reports, 3U);
  EXPECT_EQ(writer.cut_through(50).reports, 0U); // the header alone
  EXPECT_EQ(kept(writer.cut_through(50)), 0U);
  writer.forget_before(400); // a stroke ended at 400: only later cuts are asked for now
  EXPECT_EQ(writer.cut_through(450).reports, 4U);
  EXPECT_EQ(kept(writer.cut_through(500)), 5U);
}

} // namespace
} // namespace penshape::cli
