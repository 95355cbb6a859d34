// Style declarations and lengths (CSS 2 absolute units at 96 user units per inch).
#include "svg_style.hpp"

#include <cmath>
#include <cstdlib>

namespace penshape::snap {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

void set(PaintStyle& st, const std::string& name, const std::string& value) {
  if (value == "inherit" || value.empty()) return;
  if (name == "fill") st.fill = value;
  if (name == "stroke") st.stroke = value;
  if (name == "stroke-width") st.stroke_width = value;
  if (name == "fill-opacity") st.fill_opacity = value;
}

} // namespace

std::vector<std::pair<std::string, std::string>> parse_style(const std::string& declarations) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t start = 0;
  while (start <= declarations.size()) {
    auto end = declarations.find(';', start);
    if (end == std::string::npos) end = declarations.size();
    const std::string item = declarations.substr(start, end - start);
    const auto colon = item.find(':');
    if (colon != std::string::npos) {
      out.emplace_back(trim(item.substr(0, colon)), trim(item.substr(colon + 1)));
    }
    start = end + 1;
  }
  return out;
}

std::string format_style(const std::vector<std::pair<std::string, std::string>>& declarations) {
  std::string out;
  for (const auto& [k, v] : declarations) {
    if (!out.empty()) out += ';';
    out.append(k).append(":").append(v);
  }
  return out;
}

PaintStyle computed_style(const pugi::xml_node& element, PaintStyle st) {
  for (const char* name : {"fill", "stroke", "stroke-width", "fill-opacity"}) {
    if (const auto a = element.attribute(name)) set(st, name, trim(a.value()));
  }
  for (const auto& [k, v] : parse_style(element.attribute("style").value())) set(st, k, v);
  return st;
}

std::optional<double> parse_length(const std::string& text) {
  const std::string s = trim(text);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || !std::isfinite(v)) return std::nullopt;
  const std::string unit = trim(end);
  if (unit.empty() || unit == "px") return v;
  if (unit == "pt") return v * 96.0 / 72.0;
  if (unit == "pc") return v * 16.0;
  if (unit == "mm") return v * 96.0 / 25.4;
  if (unit == "cm") return v * 96.0 / 2.54;
  if (unit == "in") return v * 96.0;
  return std::nullopt;
}

} // namespace penshape::snap
