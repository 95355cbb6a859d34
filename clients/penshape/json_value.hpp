#pragma once
// JSON values as `penshape verify` reads answers back (the CLI's own `--json` output), parsed by
// nlohmann-json's SAX parser. Unlike nlohmann's own tree, numbers keep their text, so a decimal
// is read exactly (as a rational) by whoever needs it. Errors name the line and column.
#include <cstddef>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace penshape::cli {

struct JsonError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct JsonValue {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;
  bool boolean = false;
  std::string text; // a number's digits as written, or a string's decoded value
  std::vector<JsonValue> items;
  std::map<std::string, JsonValue, std::less<>> members;

  // The member, or nullptr when absent (or when this is not an object).
  [[nodiscard]] const JsonValue* find(std::string_view key) const;
};

// Every top-level value of `text`: one value, or several separated by whitespace (JSON lines).
// Throws JsonError naming line and column.
std::vector<JsonValue> parse_json_values(std::string_view text);

} // namespace penshape::cli
