#pragma once
// A minimal streaming JSON writer for `--json` output: commas and escaping are handled here so
// no subcommand assembles JSON by hand. Doubles print in shortest round-trip form; NaN and
// infinities (never valid JSON) print as null.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace penshape::cli {

class JsonWriter {
 public:
  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }
  JsonWriter& key(std::string_view name); // inside an object, before its value
  JsonWriter& string(std::string_view value);
  JsonWriter& number(double value);
  JsonWriter& integer(std::int64_t value);
  JsonWriter& boolean(bool value);
  JsonWriter& null();

  [[nodiscard]] const std::string& str() const { return out_; }

 private:
  void before_value();
  JsonWriter& open(char bracket);  // a value that opens a scope
  JsonWriter& close(char bracket); // ends the innermost scope
  std::string out_;
  std::vector<bool> first_in_scope_; // one entry per open object/array
  bool after_key_ = false;
};

} // namespace penshape::cli
