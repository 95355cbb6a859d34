// Typed reads of the config file's TOML values (config_values.hpp).
#include "config_values.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "penshape/daemon/config.hpp"

namespace penshape::daemon::config_detail {

At::At(const std::string& origin, const toml::node& node, std::string key)
    : At(origin, static_cast<std::size_t>(node.source().begin.line), std::move(key)) {}

At::At(const std::string& origin, std::size_t line, std::string key)
    : origin_(origin), line_(line), key_(std::move(key)) {}

void At::fail(const std::string& problem) const {
  fail_unkeyed(key_.empty() ? problem : key_ + ": " + problem);
}

void At::fail_unkeyed(const std::string& message) const {
  throw ConfigError(origin_ + ":" + std::to_string(line_) + ": " + message);
}

std::string describe(const toml::node& node) {
  if (node.is_table()) return "a table";
  if (node.is_array()) return "an array";
  if (const auto* text = node.as_string()) return text->get(); // as the old format showed it
  std::ostringstream text;
  node.visit([&text](const auto& value) { text << value; });
  return text.str();
}

std::size_t read_size(const At& at, const toml::node& node, std::size_t lo, std::size_t hi) {
  const auto* value = node.as_integer();
  if (value == nullptr || value->get() < 0 || static_cast<std::size_t>(value->get()) < lo ||
      static_cast<std::size_t>(value->get()) > hi) {
    at.fail("expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got '" +
            describe(node) + "'");
  }
  return static_cast<std::size_t>(value->get());
}

double read_double(const At& at, const toml::node& node) {
  if (const auto* integer = node.as_integer()) return static_cast<double>(integer->get());
  const auto* value = node.as_floating_point();
  if (value == nullptr || !std::isfinite(value->get())) {
    at.fail("expected a number, got '" + describe(node) + "'");
  }
  return value->get();
}

bool read_bool(const At& at, const toml::node& node) {
  const auto* value = node.as_boolean();
  if (value == nullptr) at.fail("expected true or false, got '" + describe(node) + "'");
  return value->get();
}

std::string read_string(const At& at, const toml::node& node) {
  const auto* value = node.as_string();
  if (value == nullptr) at.fail("expected a string in quotes, got '" + describe(node) + "'");
  return value->get();
}

} // namespace penshape::daemon::config_detail
