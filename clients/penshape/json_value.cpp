// JSON values (json_value.hpp) built from nlohmann-json's SAX events: the parser is nlohmann's;
// this only keeps each number's text (number_float hands it over; an integer's text is its
// decimal value) and bounds the nesting, so hostile input cannot build an unbounded tree.
#include "json_value.hpp"

#include <cctype>
#include <nlohmann/json.hpp>
#include <sstream>

namespace penshape::cli {

const JsonValue* JsonValue::find(std::string_view key) const {
  if (kind != Kind::kObject) return nullptr;
  const auto it = members.find(key);
  return it == members.end() ? nullptr : &it->second;
}

namespace {

constexpr std::size_t kMaxDepth = 64;

// Builds one top-level value; an error keeps where it happened (a byte offset into the value).
class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
 public:
  JsonValue root;
  std::string error;
  std::size_t error_byte = 0; // 1-based, as nlohmann counts

  bool null() override { return put(JsonValue{}); }
  bool boolean(bool b) override {
    JsonValue v;
    v.kind = JsonValue::Kind::kBool;
    v.boolean = b;
    return put(std::move(v));
  }
  bool number_integer(number_integer_t n) override { return number(std::to_string(n)); }
  bool number_unsigned(number_unsigned_t n) override { return number(std::to_string(n)); }
  bool number_float(number_float_t /*value*/, const string_t& text) override {
    return number(text);
  }
  bool string(string_t& s) override {
    JsonValue v;
    v.kind = JsonValue::Kind::kString;
    v.text = std::move(s);
    return put(std::move(v));
  }
  bool binary(binary_t& /*bytes*/) override { return false; } // not in JSON text
  bool start_object(std::size_t /*elements*/) override { return open(JsonValue::Kind::kObject); }
  bool key(string_t& k) override {
    key_ = std::move(k);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t /*elements*/) override { return open(JsonValue::Kind::kArray); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t byte, const std::string& /*token*/,
                   const nlohmann::detail::exception& e) override {
    error_byte = byte;
    error = e.what();
    // nlohmann's text is "[json.exception...] parse error at line L, column C: what": keep what.
    if (const std::size_t colon = error.find(": "); colon != std::string::npos) {
      error.erase(0, colon + 2);
    }
    return false;
  }

 private:
  bool number(std::string text) {
    JsonValue v;
    v.kind = JsonValue::Kind::kNumber;
    v.text = std::move(text);
    return put(std::move(v));
  }
  bool open(JsonValue::Kind kind) {
    if (open_.size() >= kMaxDepth) {
      error = "nested too deeply";
      return false;
    }
    JsonValue v;
    v.kind = kind;
    if (!put(std::move(v))) return false;
    open_.push_back(last_);
    return true;
  }
  bool close() {
    open_.pop_back();
    return true;
  }
  // Places `v` in the innermost open container (or as the root); remembers where it went.
  bool put(JsonValue v) {
    if (open_.empty()) {
      root = std::move(v);
      last_ = &root;
    } else if (JsonValue& parent = *open_.back(); parent.kind == JsonValue::Kind::kArray) {
      parent.items.push_back(std::move(v));
      last_ = &parent.items.back();
    } else {
      JsonValue& slot = parent.members[key_];
      slot = std::move(v);
      last_ = &slot;
    }
    return true;
  }

  std::vector<JsonValue*> open_; // containers not yet closed, outermost first
  JsonValue* last_ = nullptr;
  std::string key_;
};

[[noreturn]] void fail(std::string_view text, std::size_t offset, const std::string& what) {
  std::size_t line = 1, column = 1;
  for (std::size_t k = 0; k < offset && k < text.size(); ++k) {
    if (text[k] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  throw JsonError("JSON line " + std::to_string(line) + ", column " + std::to_string(column) +
                  ": " + what);
}

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

} // namespace

std::vector<JsonValue> parse_json_values(std::string_view text) {
  std::vector<JsonValue> out;
  std::istringstream in{std::string(text)};
  std::size_t at = 0;
  while (true) {
    while (at < text.size() && is_space(text[at])) ++at;
    if (at == text.size()) return out;
    in.clear();
    in.seekg(static_cast<std::streamoff>(at));
    TreeBuilder builder;
    // Not strict: the parse stops after one value, so JSON lines are read one value at a time.
    if (!nlohmann::json::sax_parse(in, &builder, nlohmann::json::input_format_t::json, false)) {
      if (builder.error.empty()) builder.error = "not JSON";
      fail(text, builder.error_byte == 0 ? at : at + builder.error_byte - 1, builder.error);
    }
    const auto pos = in.rdbuf()->pubseekoff(0, std::ios::cur, std::ios::in);
    at = pos < 0 ? text.size() : static_cast<std::size_t>(pos);
    // A top-level number ends at the first character that is not part of it, which the parser
    // has consumed: it must be a separator ("1x" is no value). A digit there is the number's own
    // last digit (the parser met the end of the text).
    if (builder.root.kind == JsonValue::Kind::kNumber && at > 0 && !is_space(text[at - 1]) &&
        std::isdigit(static_cast<unsigned char>(text[at - 1])) == 0) {
      fail(text, at - 1, "expected whitespace after a number");
    }
    out.push_back(std::move(builder.root));
  }
}

} // namespace penshape::cli
