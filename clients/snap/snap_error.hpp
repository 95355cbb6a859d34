#pragma once
// Bad input to `penshape snap`: the message names the place (line, element id, page/layer/stroke).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace penshape::snap {

struct SnapInputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// 1-based line of a byte offset into text (one scan: for a single message).
std::size_t line_of(std::string_view text, std::ptrdiff_t offset);

// 1-based lines of byte offsets into one text, its newlines indexed once: for a message per
// element of a large document (a scan per element would take quadratic time).
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);
  [[nodiscard]] std::size_t line(std::ptrdiff_t offset) const;

 private:
  std::vector<std::size_t> newlines_;
};

// The widest pen the reader accepts, in document units (px or pt): anything wider is a broken
// file, not a drawing.
inline constexpr double kMaxStrokeWidth = 1000.0;

} // namespace penshape::snap
