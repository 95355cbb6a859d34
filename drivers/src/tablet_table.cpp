#include "penshape/drivers/tablet_table.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <regex>
#include <sstream>

#include "penshape/drivers/report_families.hpp"
#include "tsv_rows.hpp"

namespace penshape::drivers {

std::string_view builtin_tablet_tsv(); // generated from data/tablets.tsv (tablets_tsv.cpp.in)

namespace {

constexpr std::array<std::pair<Protocol, std::string_view>, 8> kProtocols{{
    {Protocol::kHid, "hid"},
    {Protocol::kWacomHid, "wacom-hid"},
    {Protocol::kWacomGraphire, "wacom-graphire"},
    {Protocol::kWacomBamboo, "wacom-bamboo"},
    {Protocol::kWacomIntuos, "wacom-intuos"},
    {Protocol::kUcLogic, "uclogic"},
    {Protocol::kXpPen, "xppen"},
    {Protocol::kVendor, "vendor"},
}};

[[noreturn]] void fail(std::size_t line, const std::string& what) {
  throw TabletTableError("tablet table line " + std::to_string(line) + ": " + what);
}

template <typename T>
T number(std::string_view s, int base, std::size_t line, const char* what) {
  T v{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v, base);
  if (r.ec != std::errc{} || r.ptr != s.data() + s.size()) {
    fail(line, std::string("bad ") + what + " '" + std::string(s) + "'");
  }
  return v;
}

double real(std::string_view s, std::size_t line, const char* what) {
  try {
    std::size_t used = 0;
    const double v = std::stod(std::string(s), &used);
    if (used != s.size() || !(v >= 0)) throw std::invalid_argument("");
    return v;
  } catch (const std::exception&) {
    fail(line, std::string("bad ") + what + " '" + std::string(s) + "'");
  }
}

std::vector<std::uint8_t> hex_bytes(std::string_view s, std::size_t line) {
  if (s.empty() || s.size() % 2 != 0) fail(line, "bad hex '" + std::string(s) + "'");
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < s.size(); i += 2) {
    out.push_back(number<std::uint8_t>(s.substr(i, 2), 16, line, "hex byte"));
  }
  return out;
}

std::vector<InitStep> init_steps(std::string_view col, std::size_t line_no) {
  std::vector<InitStep> out;
  for (std::string_view step : tsv::split(col, ' ', tsv::Empty::kKeep)) {
    if (step.size() < 3 || step[1] != ':') fail(line_no, "bad init step");
    InitStep s;
    switch (step[0]) {
      case 'F':
        s.kind = InitStep::Kind::kFeatureReport;
        break;
      case 'O':
        s.kind = InitStep::Kind::kOutputReport;
        break;
      case 'S':
        s.kind = InitStep::Kind::kStringDescriptor;
        break;
      default:
        fail(line_no, "bad init step kind");
    }
    if (s.kind == InitStep::Kind::kStringDescriptor) {
      s.string_index = number<std::uint8_t>(step.substr(2), 10, line_no, "string index");
    } else {
      s.bytes = hex_bytes(step.substr(2), line_no);
    }
    out.push_back(std::move(s));
  }
  return out;
}

// "index=regex;index=regex": each regex must compile (ECMAScript) so matching never throws.
std::map<std::uint8_t, std::string> match_patterns(std::string_view col, std::size_t line_no) {
  std::map<std::uint8_t, std::string> out;
  for (std::string_view part : tsv::split(col, ';', tsv::Empty::kKeep)) {
    const auto eq = part.find('=');
    if (eq == std::string_view::npos) fail(line_no, "bad device_match '" + std::string(part) + "'");
    const auto index = number<std::uint8_t>(part.substr(0, eq), 10, line_no, "string index");
    std::string pattern(part.substr(eq + 1));
    try {
      (void)std::regex(pattern);
    } catch (const std::regex_error&) {
      fail(line_no, "bad device_match regex '" + pattern + "'");
    }
    out[index] = std::move(pattern);
  }
  return out;
}

} // namespace

std::string_view protocol_name(Protocol p) {
  for (const auto& [proto, name] : kProtocols) {
    if (proto == p) return name;
  }
  return "?";
}

std::optional<Protocol> protocol_from_name(std::string_view name) {
  for (const auto& [proto, n] : kProtocols) {
    if (n == name) return proto;
  }
  return std::nullopt;
}

std::vector<TabletSpec> parse_tablet_table(std::string_view tsv) {
  std::vector<TabletSpec> out;
  tsv::for_each_row(
      tsv, tsv::Empty::kKeep,
      [&](std::size_t line_no, std::string_view, const std::vector<std::string_view>& cols) {
        if (cols.size() != 13) fail(line_no, "expected 13 tab-separated columns");
        TabletSpec t;
        t.vendor_id = number<std::uint16_t>(cols[0], 16, line_no, "vid");
        t.product_id = number<std::uint16_t>(cols[1], 16, line_no, "pid");
        const ReportFamily* family = find_family(cols[2]);
        if (family == nullptr) fail(line_no, "unknown family '" + std::string(cols[2]) + "'");
        t.family = family->name;
        t.protocol = family->protocol;
        if (cols[3] != "-") t.init = init_steps(cols[3], line_no);
        t.report_length = number<std::uint32_t>(cols[4], 10, line_no, "report_len");
        t.x_max = number<std::int32_t>(cols[5], 10, line_no, "x_max");
        t.y_max = number<std::int32_t>(cols[6], 10, line_no, "y_max");
        t.pressure_max = number<std::uint32_t>(cols[7], 10, line_no, "pressure_max");
        t.width_mm = real(cols[8], line_no, "width_mm");
        t.height_mm = real(cols[9], line_no, "height_mm");
        if (t.width_mm > 0 && t.x_max > 0) t.x_resolution = t.x_max / t.width_mm;
        if (t.height_mm > 0 && t.y_max > 0) t.y_resolution = t.y_max / t.height_mm;
        t.pen_buttons = number<std::uint32_t>(cols[10], 10, line_no, "pen_buttons");
        if (cols[11] != "-") t.device_match = match_patterns(cols[11], line_no);
        t.name = std::string(cols[12]);
        if (t.name.empty()) fail(line_no, "empty name");
        out.push_back(std::move(t));
      });
  return out;
}

const std::vector<TabletSpec>& builtin_tablets() {
  static const std::vector<TabletSpec> table = parse_tablet_table(builtin_tablet_tsv());
  return table;
}

const TabletSpec* find_tablet(std::uint16_t vendor_id, std::uint16_t product_id) {
  for (const auto& t : builtin_tablets()) {
    if (t.vendor_id == vendor_id && t.product_id == product_id) return &t;
  }
  return nullptr;
}

std::vector<const TabletSpec*> find_tablets(std::uint16_t vendor_id, std::uint16_t product_id) {
  std::vector<const TabletSpec*> out;
  for (const auto& t : builtin_tablets()) {
    if (t.vendor_id == vendor_id && t.product_id == product_id) out.push_back(&t);
  }
  return out;
}

std::string string_descriptor_text(std::span<const std::uint8_t> raw) {
  if (raw.size() < 2 || raw[1] != 0x03) return {};
  const std::size_t end = std::min<std::size_t>(raw[0], raw.size());
  std::string out;
  for (std::size_t i = 2; i + 1 < end; i += 2) {
    const unsigned unit = raw[i] | (static_cast<unsigned>(raw[i + 1]) << 8);
    out.push_back(unit < 0x80 ? static_cast<char>(unit) : '?');
  }
  return out;
}

bool device_strings_match(const TabletSpec& row, const DeviceStrings& strings) {
  for (const auto& [index, pattern] : row.device_match) {
    const auto it = strings.find(index);
    if (it == strings.end() || !std::regex_search(it->second, std::regex(pattern))) return false;
  }
  return true;
}

const TabletSpec* match_tablet(std::uint16_t vendor_id, std::uint16_t product_id,
                               const DeviceStrings* strings,
                               std::span<const std::uint32_t> input_report_lengths) {
  std::vector<const TabletSpec*> rows = find_tablets(vendor_id, product_id);
  if (rows.empty()) return nullptr;
  if (strings != nullptr) {
    std::vector<const TabletSpec*> matched;
    for (const TabletSpec* r : rows) {
      if (!r->device_match.empty() && device_strings_match(*r, *strings)) matched.push_back(r);
    }
    for (const TabletSpec* r : rows) {
      if (r->device_match.empty()) matched.push_back(r);
    }
    if (!matched.empty()) rows = std::move(matched);
  }
  // Still several models and nothing told them apart: the family most of them share first.
  std::map<std::string, int> share;
  for (const TabletSpec* r : rows) ++share[r->family];
  std::stable_sort(rows.begin(), rows.end(), [&](const TabletSpec* a, const TabletSpec* b) {
    return share[a->family] > share[b->family];
  });
  for (const TabletSpec* r : rows) {
    if (std::find(input_report_lengths.begin(), input_report_lengths.end(), r->report_length) !=
        input_report_lengths.end()) {
      return r;
    }
  }
  return rows.front();
}

std::vector<std::uint8_t> device_match_indexes(std::uint16_t vendor_id, std::uint16_t product_id) {
  std::vector<std::uint8_t> out;
  for (const TabletSpec* r : find_tablets(vendor_id, product_id)) {
    for (const auto& [index, pattern] : r->device_match) {
      if (std::find(out.begin(), out.end(), index) == out.end()) out.push_back(index);
    }
  }
  return out;
}

} // namespace penshape::drivers
