#include "penshape/drivers/tablet_table.hpp"

#include <array>
#include <charconv>
#include <sstream>

namespace penshape::drivers {

std::string_view builtin_tablet_tsv(); // generated from data/tablets.tsv (tablets_tsv.cpp.in)

namespace {

constexpr std::array<std::pair<Protocol, std::string_view>, 7> kProtocols{{
    {Protocol::kHid, "hid"},
    {Protocol::kWacomHid, "wacom-hid"},
    {Protocol::kWacomGraphire, "wacom-graphire"},
    {Protocol::kWacomBamboo, "wacom-bamboo"},
    {Protocol::kWacomIntuos, "wacom-intuos"},
    {Protocol::kUcLogic, "uclogic"},
    {Protocol::kXpPen, "xppen"},
}};

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == sep) {
      out.push_back(s.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

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
  std::size_t line_no = 0;
  for (std::string_view line : split(tsv, '\n')) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line.front() == '#') continue;
    const auto cols = split(line, '\t');
    if (cols.size() != 10) fail(line_no, "expected 10 tab-separated columns");
    TabletSpec t;
    t.vendor_id = number<std::uint16_t>(cols[0], 16, line_no, "vid");
    t.product_id = number<std::uint16_t>(cols[1], 16, line_no, "pid");
    const auto proto = protocol_from_name(cols[2]);
    if (!proto) fail(line_no, "unknown protocol '" + std::string(cols[2]) + "'");
    t.protocol = *proto;
    if (cols[3] != "-") {
      for (std::string_view step : split(cols[3], ' ')) {
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
        t.init.push_back(std::move(s));
      }
    }
    t.x_max = number<std::int32_t>(cols[4], 10, line_no, "x_max");
    t.y_max = number<std::int32_t>(cols[5], 10, line_no, "y_max");
    t.pressure_max = number<std::uint32_t>(cols[6], 10, line_no, "pressure_max");
    t.x_resolution = real(cols[7], line_no, "x resolution");
    t.y_resolution = real(cols[8], line_no, "y resolution");
    t.name = std::string(cols[9]);
    if (t.name.empty()) fail(line_no, "empty name");
    out.push_back(std::move(t));
  }
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

} // namespace penshape::drivers
