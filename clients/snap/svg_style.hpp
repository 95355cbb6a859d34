#pragma once
// The few style properties snap reads (fill, stroke, stroke-width, fill-opacity), from `style`
// declarations and presentation attributes with inheritance, and a `style` rewrite that keeps
// every other declaration in order.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pugixml.hpp>

namespace penshape::snap {

struct PaintStyle {
  std::string fill = "#000000"; // SVG's initial values
  std::string stroke = "none";
  std::string stroke_width = "1";
  std::string fill_opacity = "1";
};

// `declarations` is a `style` attribute: "name:value;..." (whitespace trimmed).
std::vector<std::pair<std::string, std::string>> parse_style(const std::string& declarations);
std::string format_style(const std::vector<std::pair<std::string, std::string>>& declarations);

// The element's own properties over the inherited ones (presentation attribute, then style).
PaintStyle computed_style(const pugi::xml_node& element, PaintStyle inherited);

// A CSS length in user units: a number with an optional px, pt, pc, mm, cm or in unit.
std::optional<double> parse_length(const std::string& text);

} // namespace penshape::snap
