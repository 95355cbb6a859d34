// The page step of `penshape snap` (see page_recognizer.hpp). Grouping goes here once the core
// offers it; settings.group is then its switch.
#include "page_recognizer.hpp"

#include <algorithm>

#include "penshape/core/ink.hpp"

namespace penshape::snap {

std::vector<StrokeSnap> recognize_page(const std::vector<InkStroke>& page,
                                       const SnapSettings& settings,
                                       const StrokeRecognizer& recognize_one) {
  std::vector<StrokeSnap> out;
  out.reserve(page.size());
  for (std::size_t i = 0; i < page.size(); ++i) {
    out.push_back({i, 1, recognize_one(page[i], settings)});
  }
  return out;
}

double clean_pen_radius(const InkStroke& stroke, const SnapSettings& settings) {
  if (settings.pen_radius > 0) return settings.pen_radius;
  std::vector<double> r = stroke.radii;
  const auto mid = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
  std::nth_element(r.begin(), mid, r.end());
  return *mid;
}

Recognition recognize_in_process(const InkStroke& stroke, const SnapSettings& settings) {
  const double r = clean_pen_radius(stroke, settings);
  // A given pen radius scales the stroke's own radii so their median becomes r (the pressure
  // profile is kept).
  const double factor = settings.pen_radius > 0
                            ? settings.pen_radius / clean_pen_radius(stroke, SnapSettings{})
                            : 1.0;
  InkOptions options;
  std::vector<InkSample> samples;
  samples.reserve(stroke.points.size());
  for (std::size_t i = 0; i < stroke.points.size(); ++i) {
    samples.push_back({stroke.points[i].x, stroke.points[i].y, stroke.radii[i] * factor});
  }
  options.radius_mm = std::max_element(samples.begin(), samples.end(), [](auto& a, auto& b) {
                        return a.radius < b.radius;
                      })->radius;
  options.max_error_mm = r / 50; // the ink polygon within 2% of the clean pen's radius
  const InkPolygon ink = ink_polygon(samples, options);
  StrokeInput input;
  input.samples = stroke.points;
  input.ink = &ink;
  input.pen_radius = r;
  RecognizerConfig config;
  config.pen_radius = r;
  config.tolerance = settings.tolerance;
  return recognize(input, config);
}

} // namespace penshape::snap
