// The page step of `penshape snap` (see page_recognizer.hpp).
#include "page_recognizer.hpp"

#include <algorithm>

#include "penshape/core/deconstruct.hpp" // InvalidInput
#include "penshape/core/group_recognize.hpp"
#include "penshape/core/ink.hpp"
#include "snap_error.hpp"

namespace penshape::snap {
namespace {

// Seconds between one stroke's last sample and the next one's first: well inside the grouper's
// pause window, so nearness and group size alone decide what groups.
constexpr double kPenUpSeconds = 0.1;
constexpr double kSampleSeconds = 0.01;

// The stroke's ink polygon with its own radii, scaled so their median is the clean pen radius.
InkPolygon stroke_ink(const InkStroke& stroke, const SnapSettings& settings) {
  const double r = clean_pen_radius(stroke, settings);
  const double factor = settings.pen_radius > 0
                            ? settings.pen_radius / clean_pen_radius(stroke, SnapSettings{})
                            : 1.0;
  std::vector<InkSample> samples;
  samples.reserve(stroke.points.size());
  for (std::size_t i = 0; i < stroke.points.size(); ++i) {
    samples.push_back({stroke.points[i].x, stroke.points[i].y, stroke.radii[i] * factor});
  }
  InkOptions options;
  options.radius_mm = std::max_element(samples.begin(), samples.end(), [](auto& a, auto& b) {
                        return a.radius < b.radius;
                      })->radius;
  options.max_error_mm = r / 50; // the ink polygon within 2% of the clean pen's radius
  return ink_polygon(samples, options);
}

} // namespace

std::vector<StrokePoint> timed_samples(const InkStroke& stroke, double start) {
  std::vector<StrokePoint> out = stroke.points;
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].t = start + kSampleSeconds * static_cast<double>(i);
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

std::vector<StrokeSnap> recognize_page_in_process(const std::vector<InkStroke>& page,
                                                  const SnapSettings& settings) {
  GroupingConfig grouping;
  grouping.enabled = settings.group;
  RecognizerConfig config;
  config.pen_radius = settings.pen_radius;
  config.tolerance = settings.tolerance;
  StrokeGrouper grouper(grouping, config);
  double start = 0;
  for (const InkStroke& stroke : page) {
    try {
      const InkPolygon ink = stroke_ink(stroke, settings);
      StrokeInput input;
      input.samples = timed_samples(stroke, start);
      input.ink = &ink;
      input.pen_radius = clean_pen_radius(stroke, settings);
      start = input.samples.back().t + kPenUpSeconds;
      grouper.add(input);
    } catch (const InvalidInput& e) {
      throw SnapInputError(stroke.where + ": " + e.what());
    }
  }
  std::vector<StrokeSnap> out;
  for (GroupedShape& shape : grouper.shapes()) {
    out.push_back({std::move(shape.strokes), std::move(shape.recognition), std::move(shape.tidy)});
  }
  return out;
}

} // namespace penshape::snap
