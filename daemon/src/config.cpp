// penshaped's config file (TOML, read by toml++): each key to its field of DaemonConfig, with
// the ranges and messages of config.hpp; the TOML syntax and the migration hints for the former
// format are in config_migration.cpp, the typed reads in config_values.cpp.
#include "penshape/daemon/config.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

#include "config_migration.hpp"
#include "config_values.hpp"
#include "penshape/core/deconstruct.hpp"

namespace penshape::daemon {
namespace {

using config_detail::At;
using config_detail::read_bool;
using config_detail::read_double;
using config_detail::read_size;
using config_detail::read_string;

// A table's entries in the file's order, so the first error reported is the first in the file.
std::vector<std::pair<std::string, const toml::node*>> in_file_order(const toml::table& table) {
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [key, node] : table) entries.emplace_back(std::string(key.str()), &node);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const toml::source_position& pa = a.second->source().begin;
    const toml::source_position& pb = b.second->source().begin;
    return pa.line < pb.line || (pa.line == pb.line && pa.column < pb.column);
  });
  return entries;
}

// Applies one pen-settings key to `update`; false when the key is not a pen-settings key.
bool apply_settings_key(const At& at, const toml::node& node, PenSettingsUpdate& update) {
  const std::string& key = at.key();
  if (key == "snap_trigger") {
    const std::string word = read_string(at, node);
    update.snap_trigger = parse_snap_trigger(word);
    if (!update.snap_trigger) at.fail("expected pen_up, hold or both, got '" + word + "'");
    return true;
  }
  if (key == "snap_writing") {
    update.snap_writing = read_bool(at, node);
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
  const double parsed = read_double(at, node);
  update.*(field->second) = parsed;
  PenSettingsUpdate single;
  single.*(field->second) = parsed;
  try {
    validate(single, "");
  } catch (const SettingsError& e) {
    at.fail_unkeyed(e.what());
  }
  return true;
}

// The grouping change one key (grouping, group_*, tidy_*) asks for; false when it is not one.
bool grouping_change(const At& at, const toml::node& node, v1::GroupingSettings& change) {
  const std::string& key = at.key();
  if (key == "grouping") {
    change.set_disabled(!read_bool(at, node));
  } else if (key == "group_max_strokes") {
    change.set_max_strokes(
        static_cast<std::uint32_t>(read_size(at, node, 1, kMaxLiveGroupStrokes)));
  } else if (key == "group_max_pause_s") {
    change.set_max_pause_s(read_double(at, node));
  } else {
    const std::map<std::string, void (v1::GroupingSettings::*)(bool)> switches = {
        {"tidy_circle", &v1::GroupingSettings::set_tidy_circle},
        {"tidy_right_angles", &v1::GroupingSettings::set_tidy_right_angles},
        {"tidy_equal_sides", &v1::GroupingSettings::set_tidy_equal_sides},
        {"tidy_axis", &v1::GroupingSettings::set_tidy_axis},
        {"tidy_parallel", &v1::GroupingSettings::set_tidy_parallel},
        {"tidy_connection", &v1::GroupingSettings::set_tidy_connection}};
    const auto it = switches.find(key);
    if (it == switches.end()) return false;
    (change.*(it->second))(read_bool(at, node));
  }
  return true;
}

// Applies one grouping key to `grouping`; false when the key is not one.
bool apply_grouping_key(const At& at, const toml::node& node, GroupingConfig& grouping) {
  v1::GroupingSettings change;
  if (!grouping_change(at, node, change)) return false;
  try {
    grouping = apply_grouping(grouping, change, "group_");
  } catch (const InvalidInput& e) {
    at.fail_unkeyed(e.what());
  }
  return true;
}

// Applies one key of Limits; false when the key is not one.
bool apply_limits_key(const At& at, const toml::node& node, Limits& l) {
  const auto size = [&](std::size_t lo, std::size_t hi) { return read_size(at, node, lo, hi); };
  const std::map<std::string, std::function<void()>> handlers = {
      {"max_message_bytes", [&] { l.max_message_bytes = size(4096, 1U << 30U); }},
      {"max_vertices", [&] { l.max_vertices = size(3, 10000000); }},
      {"max_stroke_samples", [&] { l.max_stroke_samples = size(2, 10000000); }},
      {"max_call_seconds",
       [&] { l.max_call_seconds = static_cast<std::uint32_t>(size(1, 86400)); }},
      {"worker_queue_jobs", [&] { l.worker_queue_jobs = size(1, 65536); }},
      {"worker_threads", [&] { l.worker_threads = size(0, 256); }},
      {"stroke_worker_threads", [&] { l.stroke_worker_threads = size(0, 256); }},
      {"max_subscribers", [&] { l.max_subscribers = size(1, 4096); }},
      {"subscriber_queue_events", [&] { l.subscriber_queue_events = size(1, 1000000); }},
      {"max_raw_report_subscribers", [&] { l.max_raw_report_subscribers = size(0, 4096); }},
      {"max_group_keys", [&] { l.max_group_keys = size(1, 65536); }},
  };
  const auto it = handlers.find(at.key());
  if (it == handlers.end()) return false;
  it->second();
  return true;
}

void apply_global_key(const At& at, const toml::node& node, DaemonConfig& config,
                      PenSettingsUpdate& defaults) {
  const std::string& key = at.key();
  if (key == "listen") {
    config.listen = read_string(at, node);
  } else if (key == "tcp") {
    config.tcp = read_string(at, node);
  } else if (key == "tcp_allow_non_loopback") {
    config.tcp_allow_non_loopback = read_bool(at, node);
  } else if (!apply_limits_key(at, node, config.limits) &&
             !apply_grouping_key(at, node, config.grouping) &&
             !apply_settings_key(at, node, defaults)) {
    if (node.is_table()) {
      at.fail_unkeyed("unknown section '[" + key + "]' (expected [device.\"vvvv:pppp\"])");
    }
    at.fail("unknown key");
  }
}

// One [device."vvvv:pppp"] table: its pen settings, and its physical size (both or neither).
void read_device(const At& at, const toml::node& node, DaemonConfig& config,
                 const std::string& origin) {
  const std::string& device = at.key();
  const toml::table* table = node.as_table();
  if (table == nullptr) at.fail("expected a section [device.\"vvvv:pppp\"] (one per tablet model)");
  if (!is_valid_device_key(device)) {
    at.fail_unkeyed("device key '" + device +
                    "' is not vvvv:pppp (four lowercase hex digits each)");
  }
  PenSettingsUpdate& update = config.device_settings[device];
  std::pair<double, double> size{0.0, 0.0};
  std::size_t size_line = 0; // where the size was last set
  for (const auto& [key, value] : in_file_order(*table)) {
    const At key_at(origin, *value, key);
    if (key == "width_mm" || key == "height_mm") {
      const double mm = read_double(key_at, *value);
      if (!(mm > 0 && mm <= 2000)) key_at.fail("expected millimetres in (0, 2000]");
      (key == "width_mm" ? size.first : size.second) = mm;
      size_line = std::max(size_line, key_at.line());
    } else if (!apply_settings_key(key_at, *value, update)) {
      key_at.fail(
          "unknown key in a [device] section (pen_radius_mm, tolerance_fraction, "
          "precision_fraction, snap_trigger, hold_ms, hold_radius_mm, width_mm, "
          "height_mm)");
    }
  }
  if (size_line == 0) return;
  if (size.first == 0 || size.second == 0) {
    At(origin, size_line, size.first == 0 ? "width_mm" : "height_mm")
        .fail("[device.\"" + device + "\"] sets one of width_mm and height_mm: set both");
  }
  config.device_sizes[device] = size;
}

void read_devices(const At& at, const toml::node& node, DaemonConfig& config,
                  const std::string& origin) {
  const toml::table* devices = node.as_table();
  if (devices == nullptr) at.fail("expected sections [device.\"vvvv:pppp\"]");
  for (const auto& [device, table] : in_file_order(*devices)) {
    read_device(At(origin, *table, device), *table, config, origin);
  }
}

} // namespace

DaemonConfig parse_config(std::string_view text, const std::string& origin) {
  const toml::table document = config_detail::parse_toml(text, origin);
  DaemonConfig config;
  PenSettingsUpdate defaults;
  std::size_t tcp_line = 0;
  for (const auto& [key, node] : in_file_order(document)) {
    const At at(origin, *node, key);
    if (key == "device") {
      read_devices(at, *node, config, origin);
      continue;
    }
    apply_global_key(at, *node, config, defaults);
    if (key == "tcp") tcp_line = at.line();
  }
  config.settings = apply(config.settings, defaults);
  if (!config.tcp.empty()) {
    try {
      validate_tcp_address(config.tcp, config.tcp_allow_non_loopback);
    } catch (const ConfigError& e) {
      At(origin, tcp_line, "tcp").fail(e.what());
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
