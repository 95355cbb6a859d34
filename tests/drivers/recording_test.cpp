// Recordings: hid-recorder write/read round trip, usbhid-dump import, and malformed input
// reported with its byte offset.
#include "penshape/drivers/recording.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "penshape/drivers/live_recorder.hpp"
#include "penshape/drivers/replay.hpp"
#include "shared_data.hpp"

namespace penshape::drivers {
namespace {

// The generated recording in the PenPartner's protocol (every clone).
std::string penpartner_text() { return read_file(testing::penpartner_capture()); }

TEST(Recording, ReadsTheRealHidRecorderCapture) {
  PENSHAPE_SHARED_OR_SKIP(capture, testing::kPenPartnerCapture);
  const Recording r = read_hid_recorder(read_file(capture));
  EXPECT_EQ(r.identity.name, "WACOM FT-0203-UV1.4-2");
  EXPECT_EQ(r.phys, "usb-0000:00:1d.0-1.8/input0");
  EXPECT_EQ(r.identity.bus, Bus::kUsb);
  EXPECT_EQ(r.descriptor.size(), 110U);
  EXPECT_EQ(r.descriptor.front(), 0x05);
  ASSERT_EQ(r.events.size(), 874U);
  // "E: 0.015975 8 63 00 …" is the third event; "E: 0.111982 8 02 90 b7 …" is in the file too.
  EXPECT_EQ(r.events[2].time_us, 15975);
  const auto pen = std::find_if(r.events.begin(), r.events.end(),
                                [](const HidEvent& e) { return e.time_us == 111982; });
  ASSERT_NE(pen, r.events.end());
  EXPECT_EQ(pen->bytes,
            (std::vector<std::uint8_t>{0x02, 0x90, 0xb7, 0x04, 0xb9, 0x03, 0x06, 0x00}));
}

TEST(Recording, ReadsTheGeneratedRecording) {
  const Recording r = read_hid_recorder(penpartner_text());
  EXPECT_EQ(r.identity.name, "penshape generated pen (vendor-graphire)");
  EXPECT_EQ(r.identity.bus, Bus::kUsb);
  EXPECT_EQ(r.identity.vendor_id, 0x056a);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events[1].time_us, 8000); // 125 Hz
  EXPECT_EQ(r.events[0].bytes.size(), 8U);
  EXPECT_EQ(r.events[0].bytes[0], 0x02);
}

TEST(Recording, WriteThenReadIsIdentical) {
  Recording r = read_hid_recorder(penpartner_text());
  r.vendor_strings[200] = {0x0C, 0x03, 0x70, 0xC6, 0x00, 0x06, 0x7C, 0x00, 0xFF, 0x1F, 0xD8, 0x13};
  const std::string text = write_hid_recorder(r);
  const Recording back = read_hid_recorder(text);
  EXPECT_EQ(back, r);
  EXPECT_EQ(write_hid_recorder(back), text);
}

// A carriage return inside a name or physical path reads as the blank the writer writes for it,
// so the file round trips (found by the recording fuzzer).
TEST(Recording, CarriageReturnInsideAHeaderValueRoundTrips) {
  const Recording r = read_hid_recorder("P: usb 1\r2 x\nN: pen\rone\nE: 0 0\n");
  EXPECT_EQ(r.phys, "usb 1 2 x");
  EXPECT_EQ(r.identity.name, "pen one");
  EXPECT_EQ(read_hid_recorder(write_hid_recorder(r)), r);
}

TEST(Recording, DigimendDumpRoundTripsThroughHidRecorder) {
  PENSHAPE_SHARED_OR_SKIP(file, "hid/digimend-tablets/Huion_HS610/dumps/enabled/pen_pressure.txt");
  const auto dump = read_usbhid_dump(read_file(file));
  ASSERT_EQ(dump.streams.size(), 1U);
  const auto& events = dump.streams.at(0);
  ASSERT_EQ(events.size(), 1026U);
  EXPECT_EQ(events[0].time_us, 0);
  // 1557634385.633391 then 1557634385.637363.
  EXPECT_EQ(events[1].time_us, 3972);
  EXPECT_EQ(events[0].bytes.size(), 12U);
  DeviceIdentity id{Bus::kUsb, 0x256c, 0x006d, "HS610"};
  const Recording rec = recording_from_dump(dump, 0, id);
  EXPECT_EQ(read_hid_recorder(write_hid_recorder(rec)), rec);
}

TEST(Recording, DamagedDumpHeadIsSkippedAndCounted) {
  PENSHAPE_SHARED_OR_SKIP(file, "hid/digimend-tablets/Ugee_M708_v2/dumps/pen_tilt.txt");
  // The Ugee tilt dump starts with 64 KiB of NUL bytes that cut the first header.
  const auto dump = read_usbhid_dump(read_file(file));
  EXPECT_EQ(dump.damaged_blocks, 1U);
  EXPECT_EQ(dump.streams.at(1).size(), 2090U);
}

TEST(Recording, DescriptorBlocksOfADump) {
  PENSHAPE_SHARED_OR_SKIP(file, "hid/digimend-tablets/XP-Pen_G640S/hid_report_descriptors.txt");
  const auto dump = read_usbhid_dump(read_file(file));
  ASSERT_EQ(dump.descriptors.size(), 3U);
  EXPECT_EQ(dump.descriptors.at(1).front(), 0x05);
  const auto headerless = read_usbhid_dump(" 05 0D 09 02\n A1 01\n");
  EXPECT_EQ(headerless.descriptors.at(-1),
            (std::vector<std::uint8_t>{0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01}));
}

struct Bad {
  std::string text;
  std::size_t offset;
  const char* mentions;
};

TEST(Recording, MalformedHidRecorderNamesTheByteOffset) {
  const std::vector<Bad> cases = {
      {"R: 3 05 0d\n", 0, "declares 3 bytes"},
      {"R: 2 05 0d\nE: 0.000001 2 02 zz\n", 28, "hex byte"},
      {"R: 2 05 0d\nE: 1.5 1 02\nE: 1.2 1 02\n", 26, "backwards"},
      {"R: 1 05\nX: what\n", 8, "unknown line tag"},
      {"R: 1 05\nI: 3 056a\n", 8, "I: needs"},
      {"R: 1 05\nE: 0.1234567 1 02\n", 13, "fraction"},
      {"N: only a name\n", 0, "not a hid-recorder file"},
  };
  for (const auto& c : cases) {
    try {
      (void)read_hid_recorder(c.text);
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const RecordingError& e) {
      EXPECT_EQ(e.offset(), c.offset) << c.text << " -> " << e.what();
      EXPECT_NE(std::string(e.what()).find(c.mentions), std::string::npos) << e.what();
    }
  }
}

TEST(Recording, MalformedDumpNamesTheByteOffset) {
  try {
    (void)read_usbhid_dump("003:005:001:STREAM 1.0\n 0A C0 4\n");
    ADD_FAILURE();
  } catch (const RecordingError& e) {
    EXPECT_EQ(e.offset(), 30U) << e.what();
  }
  EXPECT_THROW((void)read_usbhid_dump(""), RecordingError);
}

TEST(Recording, DetectsFormats) {
  EXPECT_EQ(detect_format(penpartner_text()), RecordingFormat::kHidRecorder);
  EXPECT_EQ(detect_format("003:005:001:STREAM 1.0\n 0A\n"), RecordingFormat::kUsbhidDump);
  EXPECT_EQ(detect_format(std::string("\x05\x0d\x09\x02", 4)), RecordingFormat::kRawBytes);
}

// A source over fixed events, to record "live" without hardware.
TEST(Recording, RecordedSourceReplaysToTheSameStrokes) {
  const Recording original = read_hid_recorder(penpartner_text());
  RecordingSource source(original.events, ReplaySpeed::kAsFastAsPossible);
  std::ostringstream out;
  const std::atomic<bool> stop{false};
  const std::size_t n = record_source(source, original, out, stop, std::chrono::minutes(1));
  EXPECT_EQ(n, original.events.size());
  const Recording recorded = read_hid_recorder(out.str());
  EXPECT_EQ(recorded.descriptor, original.descriptor);
  ASSERT_EQ(recorded.events.size(), original.events.size());
  const auto a = replay(original, ReplaySpeed::kAsFastAsPossible);
  const auto b = replay(recorded, ReplaySpeed::kAsFastAsPossible);
  ASSERT_EQ(a.strokes.size(), b.strokes.size());
  for (std::size_t i = 0; i < a.strokes.size(); ++i) {
    ASSERT_EQ(a.strokes[i].samples.size(), b.strokes[i].samples.size());
    for (std::size_t k = 0; k < a.strokes[i].samples.size(); ++k) {
      // Times are relative to the first event in the re-recording.
      PenSample sa = a.strokes[i].samples[k];
      PenSample sb = b.strokes[i].samples[k];
      sa.time_us -= original.events.front().time_us;
      EXPECT_EQ(sa, sb);
    }
  }
}

} // namespace
} // namespace penshape::drivers
