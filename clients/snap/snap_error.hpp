#pragma once
// Bad input to `penshape snap`: the message names the place (line, element id, page/layer/stroke).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace penshape::snap {

struct SnapInputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// 1-based line of a byte offset into text.
std::size_t line_of(std::string_view text, std::ptrdiff_t offset);

// The widest pen the reader accepts, in document units (px or pt): anything wider is a broken
// file, not a drawing.
inline constexpr double kMaxStrokeWidth = 1000.0;

} // namespace penshape::snap
