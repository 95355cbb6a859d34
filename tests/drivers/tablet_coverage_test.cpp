// The generated tablet table: free of conflicting rows (on the committed table, in every
// clone), and covering OpenTabletDriver's configurations with the same facts (checked against
// OTD's own summary in the shared corpus, which it skips without).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "penshape/drivers/report_families.hpp"
#include "penshape/drivers/tablet_table.hpp"
#include "test_data.hpp"

namespace penshape::drivers {
namespace {

std::string match_key(const TabletSpec& t) {
  std::string k;
  for (const auto& [i, p] : t.device_match) k += std::to_string(i) + "=" + p + ";";
  return k;
}

TEST(TabletTableConflicts, NoTwoRowsForOneIdentifier) {
  // A row is picked by VID/PID, device strings and report length: two rows with the same four
  // would make the choice depend on the order of the file.
  std::map<std::tuple<int, int, std::string, std::uint32_t>, const TabletSpec*> seen;
  for (const auto& t : builtin_tablets()) {
    const auto key = std::make_tuple(t.vendor_id, t.product_id, match_key(t), t.report_length);
    const auto [it, inserted] = seen.emplace(key, &t);
    EXPECT_TRUE(inserted) << t.name << " and " << it->second->name << " share " << std::hex
                          << t.vendor_id << ":" << t.product_id;
  }
  EXPECT_GE(seen.size(), 470U);
}

TEST(TabletTableConflicts, EveryRowIsUsable) {
  for (const auto& t : builtin_tablets()) {
    const ReportFamily* f = find_family(t.family);
    ASSERT_NE(f, nullptr) << t.name;
    EXPECT_EQ(f->protocol, t.protocol) << t.name;
    // A vendor family decodes with the row's maxima; without them it would decode nothing.
    if (!f->layouts.empty() && t.protocol != Protocol::kUcLogic) {
      EXPECT_GT(t.x_max, 0) << t.name;
      EXPECT_FALSE(family_layouts(*f, t).empty()) << t.name;
    }
    // Size and maxima together give a plausible resolution (1..1000 units per mm), and a size is
    // never given without the other axis.
    EXPECT_EQ(t.width_mm > 0, t.height_mm > 0) << t.name;
    if (t.x_resolution > 0) {
      EXPECT_GE(t.x_resolution, 1.0) << t.name;
      EXPECT_LE(t.x_resolution, 1000.0) << t.name;
      EXPECT_GE(t.y_resolution, 1.0) << t.name;
      EXPECT_LE(t.y_resolution, 1000.0) << t.name;
    }
    for (const auto& s : t.init) {
      if (s.kind != InitStep::Kind::kStringDescriptor) {
        EXPECT_FALSE(s.bytes.empty()) << t.name;
      }
    }
  }
}

TEST(TabletTableConflicts, MatchPicksTheModelByStringsAndLength) {
  // 256c:006d is shared by many Huion/Gaomon models told apart by string descriptor 201.
  const DeviceStrings h640p{{201, "HUION_T173_123456"}};
  const TabletSpec* t = match_tablet(0x256c, 0x006d, &h640p, {});
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->name, "Huion H640P");
  EXPECT_DOUBLE_EQ(t->width_mm, 160.0);
  const DeviceStrings giano{{201, "HUION_M19p_000001"}};
  EXPECT_EQ(match_tablet(0x256c, 0x006d, &giano, {})->family, "huion-giano");
  // The same VID/PID and no strings: the report length decides (VEIKK A15 Pro, 13 vs 9 bytes).
  const std::uint32_t nine[] = {9};
  const std::uint32_t thirteen[] = {13};
  EXPECT_EQ(match_tablet(0x2feb, 0x0006, nullptr, nine)->family, "tablet-skip1");
  EXPECT_EQ(match_tablet(0x2feb, 0x0006, nullptr, thirteen)->family, "veikk-tilt");
  EXPECT_EQ(match_tablet(0x1234, 0x5678, nullptr, {}), nullptr);
}

// One row of OTD's configs_summary.tsv.
struct OtdRow {
  std::string name, vid, pid, length, width, height, max_x, max_y, pressure, match;
};

std::vector<OtdRow> read_otd_summary(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line); // header
  std::vector<OtdRow> out;
  while (std::getline(in, line)) {
    std::vector<std::string> c;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, '\t');) c.push_back(cell);
    c.resize(14);
    out.push_back({c[0], c[2], c[3], c[4], c[6], c[7], c[8], c[9], c[10], c[13]});
  }
  return out;
}

TEST(TabletTableCoverage, CoversOpenTabletDriverPairsWithTheirFacts) {
  PENSHAPE_SHARED_OR_SKIP(summary, "hid/opentabletdriver/configs_summary.tsv");
  const auto otd = read_otd_summary(summary);
  ASSERT_GT(otd.size(), 400U);
  std::set<std::pair<int, int>> pairs, covered;
  std::size_t facts_checked = 0;
  for (const auto& r : otd) {
    const int vid = std::stoi(r.vid, nullptr, 16);
    const int pid = std::stoi(r.pid, nullptr, 16);
    pairs.insert({vid, pid});
    const auto rows =
        find_tablets(static_cast<std::uint16_t>(vid), static_cast<std::uint16_t>(pid));
    if (!rows.empty()) covered.insert({vid, pid});
    // The row for this identifier carries OTD's physical size and maxima.
    for (const TabletSpec* t : rows) {
      const bool same_match = (r.match.empty() && t->device_match.empty()) ||
                              (!r.match.empty() && !t->device_match.empty() &&
                               r.match.find(t->device_match.begin()->second) != std::string::npos);
      if (!same_match || std::to_string(t->report_length) != (r.length.empty() ? "0" : r.length)) {
        continue;
      }
      // Merged rows ("A / B") keep the first configuration's facts.
      if (t->name.substr(0, t->name.find(" / ")) != r.name) continue;
      ++facts_checked;
      EXPECT_NEAR(t->width_mm, std::stod(r.width), 1e-3) << r.name;
      EXPECT_NEAR(t->height_mm, std::stod(r.height), 1e-3) << r.name;
      EXPECT_EQ(t->x_max, static_cast<std::int32_t>(std::stod(r.max_x))) << r.name;
      EXPECT_EQ(t->y_max, static_cast<std::int32_t>(std::stod(r.max_y))) << r.name;
      EXPECT_EQ(t->pressure_max, static_cast<std::uint32_t>(std::stod(r.pressure))) << r.name;
    }
  }
  const double coverage = static_cast<double>(covered.size()) / static_cast<double>(pairs.size());
  std::printf("OpenTabletDriver VID:PID pairs covered: %zu / %zu (%.1f%%); rows checked: %zu\n",
              covered.size(), pairs.size(), 100.0 * coverage, facts_checked);
  EXPECT_GE(coverage, 0.95);
  EXPECT_GE(facts_checked, 450U);
}

} // namespace
} // namespace penshape::drivers
