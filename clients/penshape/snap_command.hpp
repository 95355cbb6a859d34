#pragma once
// `penshape snap`: snap the strokes of an SVG or Xournal++ drawing to clean shapes.
#include <span>
#include <string_view>

namespace penshape::cli {
int run_snap(std::span<const std::string_view> args);
} // namespace penshape::cli
