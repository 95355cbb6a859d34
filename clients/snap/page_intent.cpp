// The writing/drawing decision on a document's page (see page_intent.hpp).
#include "page_intent.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "number_scanner.hpp"
#include "penshape/core/deconstruct.hpp" // InvalidInput
#include "svg_style.hpp"

namespace penshape::snap {
namespace {

// The viewBox's width (its third number), if it is a positive finite number.
std::optional<double> view_box_width(const char* text) {
  NumberScanner in(text);
  std::optional<double> v;
  for (int k = 0; k < 3; ++k) {
    in.skip_separators();
    v = in.number();
    if (!v) return std::nullopt;
  }
  if (!(*v > 0) || !std::isfinite(*v)) return std::nullopt;
  return v;
}

} // namespace

double svg_mm_per_unit(const pugi::xml_node& svg) {
  const auto box = view_box_width(svg.attribute("viewBox").value());
  const std::string width = svg.attribute("width").value();
  if (!box || width.empty() || width.back() == '%') return kSvgPixelMm;
  const auto px = parse_length(width); // in CSS pixels
  if (!px || !(*px > 0) || !std::isfinite(*px)) return kSvgPixelMm;
  const double mm = *px * kSvgPixelMm / *box;
  return std::isfinite(mm) && mm > 0 ? mm : kSvgPixelMm;
}

std::vector<IntentDecision> page_intents(const std::vector<const InkStroke*>& page,
                                         double mm_per_unit) {
  std::vector<std::vector<StrokePoint>> strokes;
  strokes.reserve(page.size());
  for (const InkStroke* s : page) {
    std::vector<StrokePoint>& pts = strokes.emplace_back(s->points);
    for (StrokePoint& p : pts) p.t = 0; // the index is no time
  }
  try {
    return decide_intent(strokes, IntentConfig{.mm_per_unit = mm_per_unit});
  } catch (const InvalidInput&) {
    return std::vector<IntentDecision>(page.size());
  }
}

} // namespace penshape::snap
