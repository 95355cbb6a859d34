#pragma once
// Typed reads of the config file's TOML values, each error naming the file, the line and the key
// ("penshaped.conf:12: max_subscribers: expected an integer in 1..4096, got '0'").
#include <toml++/toml.h>

#include <cstddef>
#include <string>

namespace penshape::daemon::config_detail {

// Where one value sits: the file, the line of its node and its key.
class At {
 public:
  At(const std::string& origin, const toml::node& node, std::string key);
  At(const std::string& origin, std::size_t line, std::string key);

  // Throws ConfigError "origin:line: key: problem" (no "key: " when the key is empty).
  [[noreturn]] void fail(const std::string& problem) const;
  // Throws ConfigError "origin:line: message" for a message that already names the key.
  [[noreturn]] void fail_unkeyed(const std::string& message) const;
  [[nodiscard]] const std::string& key() const { return key_; }
  [[nodiscard]] std::size_t line() const { return line_; }

 private:
  const std::string& origin_;
  std::size_t line_;
  std::string key_;
};

// The value as TOML writes it ('0', 'nan', 'true'), a string's text ('abc'), or "a table" /
// "an array".
std::string describe(const toml::node& node);

std::size_t read_size(const At& at, const toml::node& node, std::size_t lo, std::size_t hi);
// A finite number (an integer is read as one too).
double read_double(const At& at, const toml::node& node);
bool read_bool(const At& at, const toml::node& node);
std::string read_string(const At& at, const toml::node& node);

} // namespace penshape::daemon::config_detail
