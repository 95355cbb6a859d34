// The config file as TOML, and the migration hints for lines of the former format
// (config_migration.hpp).
#include "config_migration.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <vector>

#include "penshape/daemon/config.hpp"

namespace penshape::daemon::config_detail {
namespace {

// The keys whose values are strings: the former format wrote them unquoted.
constexpr std::array<std::string_view, 3> kStringKeys = {"listen", "tcp", "snap_trigger"};

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// A former-format line has no quotes before its comment, so '#' always starts one.
std::string_view without_comment(std::string_view line) {
  return trim(line.substr(0, line.find('#')));
}

// `text` as a TOML basic string.
std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20U) {
      std::array<char, 8> escape{};
      std::snprintf(escape.data(), escape.size(), "\\u%04x", static_cast<unsigned>(c));
      out += escape.data();
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// `[device 056a:0010]` or `[device "056a:0010"]`: what to write instead.
std::optional<std::string> device_header_hint(std::string_view line) {
  if (line.size() < 2 || line.front() != '[' || line.back() != ']') return std::nullopt;
  const std::string_view inner = trim(line.substr(1, line.size() - 2));
  if (inner.size() < 7 || inner.substr(0, 6) != "device" || (inner[6] != ' ' && inner[6] != '\t')) {
    return std::nullopt;
  }
  std::string_view key = trim(inner.substr(7));
  if (key.size() >= 2 && key.front() == '"' && key.back() == '"') {
    key = key.substr(1, key.size() - 2);
  }
  return std::string(line) + ": write [device." + quoted(key) + "]";
}

// `listen = unix:/run/p.sock`: the same string in quotes.
std::optional<std::string> unquoted_string_hint(std::string_view line) {
  const auto eq = line.find('=');
  if (eq == std::string_view::npos) return std::nullopt;
  const std::string_view key = trim(line.substr(0, eq));
  const std::string_view value = trim(line.substr(eq + 1));
  const bool string_key =
      std::find(kStringKeys.begin(), kStringKeys.end(), key) != kStringKeys.end();
  if (!string_key || value.empty() || value.front() == '"' || value.front() == '\'') {
    return std::nullopt;
  }
  return std::string(key) + ": write the value in quotes: " + std::string(key) + " = " +
         quoted(value);
}

struct Hint {
  std::size_t line;
  std::string text;
};

std::vector<Hint> former_format_hints(std::string_view text) {
  std::vector<Hint> hints;
  std::size_t number = 0;
  while (!text.empty()) {
    ++number;
    const std::size_t newline = text.find('\n');
    const std::string_view line = without_comment(text.substr(0, newline));
    text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
    std::optional<std::string> hint = device_header_hint(line);
    if (!hint) hint = unquoted_string_hint(line);
    if (hint) hints.push_back({number, std::move(*hint)});
  }
  return hints;
}

// The key of a `key = value` line (empty when the line is not one).
std::string key_of_line(std::string_view text, std::size_t number) {
  for (std::size_t n = 1; n < number && !text.empty(); ++n) {
    const std::size_t newline = text.find('\n');
    text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
  }
  const std::string_view line = without_comment(text.substr(0, text.find('\n')));
  const auto eq = line.find('=');
  if (eq == std::string_view::npos || line.starts_with('[')) return "";
  return std::string(trim(line.substr(0, eq)));
}

[[noreturn]] void fail_syntax(std::string_view text, const std::string& origin,
                              const toml::parse_error& error) {
  const std::size_t line = error.source().begin.line;
  const std::vector<Hint> hints = former_format_hints(text);
  const bool former = std::any_of(hints.begin(), hints.end(),
                                  [line](const Hint& hint) { return hint.line == line; });
  if (former) { // every former-format line at once: the whole migration in one message
    std::string message;
    for (const Hint& hint : hints) {
      message += origin + ":" + std::to_string(hint.line) + ": " + hint.text + "\n";
    }
    throw ConfigError(message + origin +
                      ": the config file is TOML: strings in quotes, [device.\"vvvv:pppp\"] "
                      "sections (README, \"Config file\")");
  }
  const std::string key = key_of_line(text, line);
  throw ConfigError(origin + ":" + std::to_string(line) + ": " + (key.empty() ? "" : key + ": ") +
                    "not TOML (column " + std::to_string(error.source().begin.column) +
                    "): " + std::string(error.description()));
}

} // namespace

toml::table parse_toml(std::string_view text, const std::string& origin) {
  try {
    return toml::parse(text, std::string_view(origin));
  } catch (const toml::parse_error& error) {
    fail_syntax(text, origin, error);
  }
}

} // namespace penshape::daemon::config_detail
