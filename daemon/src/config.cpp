#include "penshape/daemon/config.hpp"

#include <arpa/inet.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "penshape/core/deconstruct.hpp"

namespace penshape::daemon {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) {
    s.remove_prefix(1);
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

class LineContext {
 public:
  LineContext(const std::string& origin, std::size_t line) : origin_(origin), line_(line) {}
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    std::string where = origin_ + ":" + std::to_string(line_) + ": ";
    if (!key.empty()) where += key + ": ";
    throw ConfigError(where + problem);
  }

 private:
  const std::string& origin_;
  std::size_t line_;
};

std::size_t parse_size(const LineContext& at, const std::string& key, std::string_view value,
                       std::size_t lo, std::size_t hi) {
  std::size_t result = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), result);
  if (ec != std::errc() || end != value.data() + value.size() || result < lo || result > hi) {
    at.fail(key, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                     ", got '" + std::string(value) + "'");
  }
  return result;
}

double parse_double(const LineContext& at, const std::string& key, std::string_view value) {
  const std::string text(value);
  char* end = nullptr;
  errno = 0;
  const double result = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno != 0 || !std::isfinite(result)) {
    at.fail(key, "expected a number, got '" + text + "'");
  }
  return result;
}

bool parse_bool(const LineContext& at, const std::string& key, std::string_view value) {
  if (value == "true") return true;
  if (value == "false") return false;
  at.fail(key, "expected true or false, got '" + std::string(value) + "'");
}

// Applies one pen-settings key to `update`; false when `key` is not a pen-settings key.
bool apply_settings_key(const LineContext& at, const std::string& key, std::string_view value,
                        PenSettingsUpdate& update) {
  if (key == "snap_trigger") {
    update.snap_trigger = parse_snap_trigger(std::string(value));
    if (!update.snap_trigger) {
      at.fail(key, "expected pen_up, hold or both, got '" + std::string(value) + "'");
    }
    return true;
  }
  if (key == "snap_writing") {
    update.snap_writing = parse_bool(at, key, value);
    return true;
  }
  using Field = std::optional<double> PenSettingsUpdate::*;
  const std::map<std::string, Field> fields = {
      {"pen_radius_mm", &PenSettingsUpdate::pen_radius_mm},
      {"tolerance_fraction", &PenSettingsUpdate::tolerance_fraction},
      {"precision_fraction", &PenSettingsUpdate::precision_fraction},
      {"hold_ms", &PenSettingsUpdate::hold_ms},
      {"hold_radius_mm", &PenSettingsUpdate::hold_radius_mm}};
  const auto field = fields.find(key);
  if (field == fields.end()) return false;
  const double parsed = parse_double(at, key, value);
  update.*(field->second) = parsed;
  PenSettingsUpdate single;
  single.*(field->second) = parsed;
  try {
    validate(single, "");
  } catch (const SettingsError& e) {
    at.fail("", e.what());
  }
  return true;
}

// Applies one grouping key (grouping, group_*, tidy_*) to `grouping`; false when `key` is not one.
bool apply_grouping_key(const LineContext& at, const std::string& key, std::string_view value,
                        GroupingConfig& grouping) {
  v1::GroupingSettings change;
  if (key == "grouping") {
    change.set_disabled(!parse_bool(at, key, value));
  } else if (key == "group_max_strokes") {
    change.set_max_strokes(
        static_cast<std::uint32_t>(parse_size(at, key, value, 1, kMaxLiveGroupStrokes)));
  } else if (key == "group_max_pause_s") {
    change.set_max_pause_s(parse_double(at, key, value));
  } else if (key.rfind("tidy_", 0) == 0) {
    const std::map<std::string, void (v1::GroupingSettings::*)(bool)> switches = {
        {"tidy_circle", &v1::GroupingSettings::set_tidy_circle},
        {"tidy_right_angles", &v1::GroupingSettings::set_tidy_right_angles},
        {"tidy_equal_sides", &v1::GroupingSettings::set_tidy_equal_sides},
        {"tidy_axis", &v1::GroupingSettings::set_tidy_axis},
        {"tidy_parallel", &v1::GroupingSettings::set_tidy_parallel},
        {"tidy_connection", &v1::GroupingSettings::set_tidy_connection}};
    const auto it = switches.find(key);
    if (it == switches.end()) return false;
    (change.*(it->second))(parse_bool(at, key, value));
  } else {
    return false;
  }
  try {
    grouping = apply_grouping(grouping, change, "group_");
  } catch (const InvalidInput& e) {
    at.fail("", e.what());
  }
  return true;
}

void apply_global_key(const LineContext& at, const std::string& key, std::string_view value,
                      DaemonConfig& config, PenSettingsUpdate& defaults) {
  Limits& l = config.limits;
  const std::map<std::string, std::function<void()>> handlers = {
      {"listen", [&] { config.listen = std::string(value); }},
      {"tcp", [&] { config.tcp = std::string(value); }},
      {"tcp_allow_non_loopback",
       [&] { config.tcp_allow_non_loopback = parse_bool(at, key, value); }},
      {"max_message_bytes",
       [&] { l.max_message_bytes = parse_size(at, key, value, 4096, 1U << 30U); }},
      {"max_vertices", [&] { l.max_vertices = parse_size(at, key, value, 3, 10'000'000); }},
      {"max_stroke_samples",
       [&] { l.max_stroke_samples = parse_size(at, key, value, 2, 10'000'000); }},
      {"max_call_seconds",
       [&] {
         l.max_call_seconds = static_cast<std::uint32_t>(parse_size(at, key, value, 1, 86'400));
       }},
      {"worker_queue_jobs", [&] { l.worker_queue_jobs = parse_size(at, key, value, 1, 65'536); }},
      {"worker_threads", [&] { l.worker_threads = parse_size(at, key, value, 0, 256); }},
      {"stroke_worker_threads",
       [&] { l.stroke_worker_threads = parse_size(at, key, value, 0, 256); }},
      {"max_subscribers", [&] { l.max_subscribers = parse_size(at, key, value, 1, 4'096); }},
      {"subscriber_queue_events",
       [&] { l.subscriber_queue_events = parse_size(at, key, value, 1, 1'000'000); }},
      {"max_raw_report_subscribers",
       [&] { l.max_raw_report_subscribers = parse_size(at, key, value, 0, 4'096); }},
      {"max_group_keys", [&] { l.max_group_keys = parse_size(at, key, value, 1, 65'536); }},
  };
  const auto it = handlers.find(key);
  if (it != handlers.end()) {
    it->second();
    return;
  }
  if (apply_grouping_key(at, key, value, config.grouping)) return;
  if (!apply_settings_key(at, key, value, defaults)) at.fail(key, "unknown key");
}

} // namespace

DaemonConfig parse_config(std::string_view text, const std::string& origin) {
  DaemonConfig config;
  PenSettingsUpdate defaults;
  std::string section;        // "" or a device key
  std::set<std::string> seen; // "section/key"
  std::size_t line_number = 0;
  std::size_t tcp_line = 0;
  std::map<std::string, std::pair<double, double>> sizes; // device key -> (width, height) mm
  std::map<std::string, std::size_t> size_lines;          // where each was last set
  while (!text.empty()) {
    ++line_number;
    const std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
    const LineContext at(origin, line_number);
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
      line = line.substr(0, hash);
    }
    line = trim(line);
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']') at.fail("", "a section header ends with ']'");
      const std::string_view inner = trim(line.substr(1, line.size() - 2));
      if (inner.substr(0, 7) != "device ") {
        at.fail("", "unknown section '[" + std::string(inner) + "]' (expected [device vvvv:pppp])");
      }
      section = std::string(trim(inner.substr(7)));
      if (section.size() >= 2 && section.front() == '"' && section.back() == '"') {
        section = section.substr(1, section.size() - 2);
      }
      if (section.empty() || !is_valid_device_key(section)) {
        at.fail("",
                "device key '" + section + "' is not vvvv:pppp (four lowercase hex digits each)");
      }
      if (config.device_settings.count(section) != 0) {
        at.fail("", "section [device " + section + "] appears twice");
      }
      config.device_settings[section] = {};
      continue;
    }
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos) at.fail("", "expected 'key = value'");
    const std::string key(trim(line.substr(0, eq)));
    const std::string_view value = trim(line.substr(eq + 1));
    if (key.empty()) at.fail("", "expected 'key = value'");
    if (!seen.insert(section + "/" + key).second) at.fail(key, "set twice");
    if (section.empty()) {
      apply_global_key(at, key, value, config, defaults);
      if (key == "tcp") tcp_line = line_number;
    } else if (key == "width_mm" || key == "height_mm") {
      const double mm = parse_double(at, key, value);
      if (!(mm > 0 && mm <= 2000)) at.fail(key, "expected millimetres in (0, 2000]");
      auto& size = sizes[section];
      (key == "width_mm" ? size.first : size.second) = mm;
      size_lines[section] = line_number;
    } else if (!apply_settings_key(at, key, value, config.device_settings[section])) {
      at.fail(key,
              "unknown key in a [device] section (pen_radius_mm, tolerance_fraction, "
              "precision_fraction, snap_trigger, hold_ms, hold_radius_mm, width_mm, height_mm)");
    }
  }
  for (const auto& [key, size] : sizes) {
    if (size.first == 0 || size.second == 0) {
      LineContext(origin, size_lines[key])
          .fail(size.first == 0 ? "width_mm" : "height_mm",
                "[device " + key + "] sets one of width_mm and height_mm: set both");
    }
    config.device_sizes[key] = size;
  }
  config.settings = apply(config.settings, defaults);
  if (!config.tcp.empty()) {
    try {
      validate_tcp_address(config.tcp, config.tcp_allow_non_loopback);
    } catch (const ConfigError& e) {
      LineContext(origin, tcp_line).fail("tcp", e.what());
    }
  }
  return config;
}

DaemonConfig load_config_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot read the config file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ConfigError(path + ": read error");
  return parse_config(text.str(), path);
}

void validate_tcp_address(const std::string& address, bool allow_non_loopback) {
  const std::size_t colon = address.rfind(':');
  if (colon == std::string::npos || colon == 0) {
    throw ConfigError("'" + address + "' is not HOST:PORT");
  }
  std::string host = address.substr(0, colon);
  const std::string port = address.substr(colon + 1);
  unsigned long port_number = 0;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), port_number);
  if (port.empty() || ec != std::errc() || end != port.data() + port.size() ||
      port_number > 65535) {
    throw ConfigError("port '" + port + "' is not in 0..65535");
  }
  bool loopback = false;
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
    host = host.substr(1, host.size() - 2);
    in6_addr v6{};
    if (inet_pton(AF_INET6, host.c_str(), &v6) != 1) {
      throw ConfigError("'" + host + "' is not an IPv6 address");
    }
    loopback = IN6_IS_ADDR_LOOPBACK(&v6);
  } else if (host == "localhost") {
    loopback = true;
  } else {
    in_addr v4{};
    if (inet_pton(AF_INET, host.c_str(), &v4) != 1) {
      throw ConfigError("'" + host + "' is not an IPv4 address, [IPv6] or localhost");
    }
    loopback = (ntohl(v4.s_addr) >> 24U) == 127U;
  }
  if (!loopback && !allow_non_loopback) {
    throw ConfigError("'" + host +
                      "' is not a loopback address; set tcp_allow_non_loopback = true (or pass "
                      "--tcp-allow-non-loopback) to listen beyond this machine");
  }
}

} // namespace penshape::daemon
