// Real report streams decode to plausible pen samples: the Wacom PenPartner hid-recorder capture
// and every DIGImend usbhid-dump (firmware and vendor mode), from the shared corpus (skipped
// without it); and the generated recording in the PenPartner's protocol, in every clone. Plausible
// = coordinates within the maxima, pressure varying in the pressure dumps, tilt in the tilt dumps,
// buttons in the button dumps, and strokes cut from them.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>

#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"
#include "shared_data.hpp"

namespace penshape::drivers {
namespace {

struct Summary {
  std::size_t samples = 0, tip_samples = 0;
  std::set<std::uint32_t> pressures;
  std::set<std::pair<int, int>> tilts;
  std::uint32_t buttons_seen = 0;
};

Summary summarise(const ReplayResult& r) {
  Summary s;
  for (const auto& p : r.samples) {
    ++s.samples;
    s.tip_samples += p.tip;
    s.pressures.insert(p.pressure);
    s.tilts.insert({p.tilt_x, p.tilt_y});
    s.buttons_seen |= p.buttons;
    EXPECT_GE(p.x, 0);
    EXPECT_LE(p.x, r.tablet.x_max);
    EXPECT_GE(p.y, 0);
    EXPECT_LE(p.y, r.tablet.y_max);
    EXPECT_LE(p.pressure, r.tablet.pressure_max);
  }
  for (const auto& st : r.strokes) {
    EXPECT_GE(st.samples.size(), 2U);
    EXPECT_TRUE(st.samples.front().tip);
    EXPECT_FALSE(st.samples.back().tip);
  }
  return s;
}

TEST(RealStreams, GeneratedGraphireRecording) {
  const auto rec = read_hid_recorder(read_file(testing::penpartner_capture()));
  EXPECT_EQ(rec.identity.vendor_id, 0x056a);
  EXPECT_EQ(rec.identity.product_id, 0x0061);
  const auto r = replay(rec, ReplaySpeed::kAsFastAsPossible);
  EXPECT_EQ(r.tablet.x_max, 3250);
  EXPECT_EQ(r.tablet.pressure_max, 255U);
  EXPECT_EQ(r.layout, "wacom-graphire");
  EXPECT_EQ(r.size_source, SizeSource::kTable);
  const Summary s = summarise(r);
  EXPECT_EQ(r.counters.pen_samples, rec.events.size());
  EXPECT_GT(s.pressures.size(), 20U) << "pressure must vary";
  EXPECT_EQ(r.strokes.size(), 3U); // recordings/generated-graphire.expected
}

TEST(RealStreams, WacomPenPartnerCapture) {
  PENSHAPE_SHARED_OR_SKIP(capture, testing::kPenPartnerCapture);
  const auto rec = read_hid_recorder(read_file(capture));
  EXPECT_EQ(rec.identity.vendor_id, 0x056a);
  EXPECT_EQ(rec.identity.product_id, 0x0061);
  ASSERT_EQ(rec.events.size(), 874U);
  const auto r = replay(rec, ReplaySpeed::kAsFastAsPossible);
  EXPECT_EQ(r.tablet.x_max, 3250);
  EXPECT_EQ(r.tablet.y_max, 2320);
  EXPECT_EQ(r.tablet.pressure_max, 255U);
  // The Graphire report family, sized by the table (the Linux wacom driver's 50 units/mm).
  EXPECT_EQ(r.layout, "wacom-graphire");
  EXPECT_EQ(r.size_source, SizeSource::kTable);
  EXPECT_NEAR(r.tablet.width_mm(), 65.0, 1e-9);
  const Summary s = summarise(r);
  // Report 0x02 (pen) vs 0x63 (a status report the descriptor declares): counted apart.
  std::size_t pen_reports = 0;
  for (const auto& e : rec.events) pen_reports += e.bytes[0] == 0x02;
  EXPECT_EQ(r.counters.pen_samples, pen_reports);
  EXPECT_EQ(r.counters.other_reports + r.counters.pen_samples, rec.events.size());
  EXPECT_EQ(r.counters.junk_reports, 0U);
  EXPECT_EQ(s.tip_samples, 38U) << "22 frames 0x91 and 16 frames 0x95 have the tip bit";
  EXPECT_GT(s.pressures.size(), 50U) << "pressure must vary";
  EXPECT_NE(s.buttons_seen & kBarrel2, 0U) << "0x94 frames carry the second side switch";
  EXPECT_GE(r.strokes.size(), 3U);
  std::printf("PenPartner: %zu samples, %zu with tip, %zu pressures, %zu strokes\n", s.samples,
              s.tip_samples, s.pressures.size(), r.strokes.size());
}

struct Tablet {
  std::string dir;
  std::uint16_t vid, pid;
  std::vector<std::uint8_t> vendor_string_200; // the tablet's answer to string 200, if probed
};

std::vector<std::uint8_t> probe_string(const std::filesystem::path& probe, const std::string& idx) {
  std::ifstream in(probe);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("S " + idx + " ", 0) == 0) return parse_hex_bytes(line.substr(2 + idx.size()));
  }
  return {};
}

// The descriptor of interface `iface` as the tablet sent it before any driver touched it.
std::vector<std::uint8_t> original_descriptor(const std::filesystem::path& tablet, int iface) {
  const auto rd = tablet / "rd" / ("original" + std::to_string(iface) + ".txt");
  if (std::filesystem::exists(rd)) {
    const auto dump = read_usbhid_dump(read_file(rd));
    return dump.descriptors.begin()->second;
  }
  const auto dump = read_usbhid_dump(read_file(tablet / "hid_report_descriptors.txt"));
  return dump.descriptors.at(iface);
}

TEST(RealStreams, EveryDigimendDumpDecodes) {
  PENSHAPE_SHARED_OR_SKIP(base, "hid/digimend-tablets");
  std::size_t files = 0;
  std::printf("%-44s %4s %6s %6s %5s %5s %5s %6s %5s %4s %6s\n", "dump", "mode", "pen", "tip",
              "press", "tilts", "btns", "other", "junk", "oor", "strokes");
  for (const auto& tdir : std::filesystem::directory_iterator(base)) {
    const std::string index = read_file(tdir.path() / "index.md");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(index, m, std::regex("VID: \"(\\w+)\"[\\s\\S]*PID: \"(\\w+)\"")));
    DeviceIdentity id;
    id.bus = Bus::kUsb;
    id.vendor_id = static_cast<std::uint16_t>(std::stoul(m[1], nullptr, 16));
    id.product_id = static_cast<std::uint16_t>(std::stoul(m[2], nullptr, 16));
    const auto s200 = probe_string(tdir.path() / "probe.txt", "C8");
    for (const auto& f : std::filesystem::recursive_directory_iterator(tdir.path() / "dumps")) {
      const std::string name = f.path().filename().string();
      if (!f.is_regular_file() || name == "descriptors.txt") continue;
      ++files;
      const auto dump = read_usbhid_dump(read_file(f.path()));
      ASSERT_FALSE(dump.streams.empty()) << f.path();
      // The interface with most reports is the one the dump was about.
      int iface = -1;
      std::size_t most = 0;
      for (const auto& [i, events] : dump.streams) {
        if (events.size() > most) {
          most = events.size();
          iface = i;
        }
      }
      Recording rec = recording_from_dump(dump, iface, id);
      rec.descriptor = original_descriptor(tdir.path(), iface);
      // Vendor mode: the dump's reports use UC-Logic's vendor report 0x08 (the tablet answered
      // string descriptor 200 before the capture); firmware mode otherwise.
      const bool vendor = std::any_of(rec.events.begin(), rec.events.end(), [](const HidEvent& e) {
        return e.bytes.size() == 12 && e.bytes[0] == 0x08;
      });
      if (vendor) {
        ASSERT_FALSE(s200.empty()) << "vendor-mode dump without probe: " << f.path();
        rec.vendor_strings[200] = s200;
      }
      const auto r = replay(rec, ReplaySpeed::kAsFastAsPossible);
      const Summary s = summarise(r);
      const std::string rel = std::filesystem::relative(f.path(), base).string();
      // Vendor mode decodes through the UC-Logic report family, sized by the probe; firmware
      // mode through the descriptor. Either way the size is known (never device units as mm).
      if (vendor) {
        EXPECT_EQ(r.layout.rfind("uclogic", 0), 0U) << rel << ": " << r.layout;
        EXPECT_EQ(r.size_source, SizeSource::kProbe) << rel;
      } else if (r.counters.pen_samples > 0) {
        EXPECT_EQ(r.layout, "hid") << rel;
      }
      EXPECT_NE(r.size_source, SizeSource::kUnknown) << rel;
      std::printf("  family %s, layout %s, size %.1f x %.1f mm from %s\n", r.family.c_str(),
                  r.layout.c_str(), r.tablet.width_mm(), r.tablet.height_mm(),
                  std::string(size_source_name(r.size_source)).c_str());
      std::printf("%-44s %4s %6zu %6zu %5zu %5zu %5x %6llu %5llu %4llu %6zu\n", rel.c_str(),
                  vendor ? "vend" : "firm", s.samples, s.tip_samples, s.pressures.size(),
                  s.tilts.size(), s.buttons_seen,
                  static_cast<unsigned long long>(r.counters.other_reports),
                  static_cast<unsigned long long>(r.counters.junk_reports),
                  static_cast<unsigned long long>(r.counters.out_of_range), r.strokes.size());
      // Almost every report of a pen dump is a pen sample; frame dumps are pad reports.
      if (name.rfind("pen_", 0) == 0) {
        EXPECT_GT(s.samples, r.counters.reports * 95 / 100) << rel;
        if (name != "pen_buttons.txt") { // buttons were pressed while hovering
          EXPECT_GT(s.tip_samples, 0U) << rel;
          EXPECT_GE(r.strokes.size(), 1U) << rel;
        }
        EXPECT_LE(r.counters.out_of_range, r.counters.reports / 100) << rel;
      }
      if (name == "pen_pressure.txt") {
        EXPECT_GT(s.pressures.size(), 100U) << rel;
      }
      if (name == "pen_tilt.txt") {
        // Only the HS610 has tilt; the Ugee M708 and H610 tilt dumps carry none (their tilt
        // bytes are zero or absent), and must decode as untilted.
        if (rel.rfind("Huion_HS610", 0) == 0) {
          EXPECT_GT(s.tilts.size(), 50U) << rel;
        } else {
          EXPECT_EQ(s.tilts, (std::set<std::pair<int, int>>{{0, 0}})) << rel;
        }
      }
      if (name == "pen_buttons.txt") {
        EXPECT_NE(s.buttons_seen & (kBarrel1 | kBarrel2), 0U) << rel;
      }
      if (name.rfind("frame_", 0) == 0) {
        // Pad reports are "other"; the H610's soft keys are touched with the pen, so its frame
        // dumps are pen samples. Nothing is junk.
        EXPECT_EQ(r.counters.junk_reports, 0U) << rel;
        EXPECT_EQ(r.counters.other_reports + r.counters.pen_samples, r.counters.reports) << rel;
      }
    }
  }
  EXPECT_GE(files, 30U);
}

} // namespace
} // namespace penshape::drivers
