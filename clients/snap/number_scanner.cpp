// SVG's number grammar, scanned by hand (the characters are checked here, the value converted by
// std::strtod on the exact span).
#include "number_scanner.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace penshape::snap {
namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
} // namespace

void NumberScanner::skip_spaces() {
  while (!done() && is_space(peek())) ++i_;
}

void NumberScanner::skip_separators() {
  while (!done() && (is_space(peek()) || peek() == ',')) ++i_;
}

bool NumberScanner::at_number() const {
  if (done()) return false;
  const char c = peek();
  return is_digit(c) || c == '.' || c == '-' || c == '+';
}

std::optional<double> NumberScanner::number() {
  std::size_t j = i_;
  if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
  std::size_t digits = 0;
  while (j < s_.size() && is_digit(s_[j])) ++j, ++digits;
  if (j < s_.size() && s_[j] == '.') {
    ++j;
    while (j < s_.size() && is_digit(s_[j])) ++j, ++digits;
  }
  if (digits == 0) return std::nullopt;
  if (j < s_.size() && (s_[j] == 'e' || s_[j] == 'E')) {
    std::size_t k = j + 1;
    if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
    if (k < s_.size() && is_digit(s_[k])) {
      while (k < s_.size() && is_digit(s_[k])) ++k;
      j = k;
    }
  }
  const std::string span(s_.substr(i_, j - i_));
  const double v = std::strtod(span.c_str(), nullptr);
  if (!std::isfinite(v)) return std::nullopt;
  i_ = j;
  return v;
}

std::optional<bool> NumberScanner::flag() {
  if (done() || (peek() != '0' && peek() != '1')) return std::nullopt;
  return take() == '1';
}

} // namespace penshape::snap
