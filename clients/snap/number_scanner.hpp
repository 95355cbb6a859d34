#pragma once
// Reads the numbers of SVG attribute micro-syntaxes (path data, transform lists, point lists):
// SVG's number grammar (sign, digits, '.', exponent; "1.5.5" is two numbers, "-1-2" too), with
// whitespace and commas between. Internal to the snap library.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace penshape::snap {

class NumberScanner {
 public:
  explicit NumberScanner(std::string_view text) : s_(text) {}
  [[nodiscard]] bool done() const { return i_ >= s_.size(); }
  [[nodiscard]] char peek() const { return s_[i_]; }
  char take() { return s_[i_++]; }
  [[nodiscard]] std::string where() const { return std::to_string(i_); }
  [[nodiscard]] std::size_t offset() const { return i_; }
  void skip_spaces();
  void skip_separators(); // spaces and at most... any commas
  // A number at the cursor (finite), or nullopt (cursor unchanged).
  std::optional<double> number();
  // An arc flag: a single '0' or '1'.
  std::optional<bool> flag();
  // Whether a number starts here.
  [[nodiscard]] bool at_number() const;

 private:
  std::string_view s_;
  std::size_t i_ = 0;
};

} // namespace penshape::snap
