// The measures the writing/drawing model weighs, per stroke of a page (intent.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "page_context.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/intent.hpp"
#include "stroke_measures.hpp"

namespace penshape {
namespace {

constexpr double kPen = 0.35;         // mm: keeps the logarithms of dots and lines finite
constexpr double kTypicalSpeed = 50;  // mm/s, centres the speed feature
constexpr double kTypicalPause = 0.3; // s

IntentFeatures features_of(const intent::StrokeMeasures& m, const intent::Context& c) {
  const double h = c.writing_height;
  const double height = m.box.height() + kPen;
  const double width = m.box.width() + kPen;
  const double size = m.size + kPen;
  const double length = m.length + kPen;
  const double loops = m.turning / (2 * std::numbers::pi);
  return {std::log(size),
          std::log(height),
          std::log(length),
          std::log(size / h),
          std::log(height / h),
          std::log(length / h),
          std::log1p(loops),
          std::log1p(loops * h / length),
          std::log1p(m.reversals),
          m.straightness,
          m.closedness,
          std::log(height / width),
          std::log1p(c.near),
          std::log1p(c.on_line),
          std::log1p(c.inside),
          std::log(0.1 + c.gap),
          c.small_run,
          m.timed ? 1.0 : 0.0,
          m.timed ? std::log(std::max(m.speed, 1.0) / kTypicalSpeed) : 0.0,
          m.timed ? std::log((0.05 + c.pause) / kTypicalPause) : 0.0,
          std::log(h)};
}

} // namespace

const std::array<std::string_view, kIntentFeatureCount>& intent_feature_names() {
  static const std::array<std::string_view, kIntentFeatureCount> kNames{
      "log_size", "log_height",   "log_length",    "rel_size",     "rel_height", "rel_length",
      "loops",    "loop_density", "reversals",     "straightness", "closedness", "aspect",
      "near",     "on_line",      "inside",        "gap",          "small_run",  "timed",
      "speed",    "pause",        "writing_height"};
  return kNames;
}

IntentFeatures intent::features_at(std::span<const StrokeMeasures> all, std::size_t i,
                                   std::size_t window) {
  return features_of(all[i], context_of(all, i, window));
}

std::vector<IntentFeatures> intent_features(std::span<const IntentStroke> page,
                                            const IntentConfig& config) {
  if (!(config.mm_per_unit > 0) || !std::isfinite(config.mm_per_unit)) {
    throw InvalidInput("intent: mm_per_unit must be positive and finite");
  }
  std::vector<intent::StrokeMeasures> measures;
  measures.reserve(page.size());
  for (const IntentStroke& s : page)
    measures.push_back(intent::measure_stroke(s, config.mm_per_unit));
  std::vector<IntentFeatures> out;
  out.reserve(page.size());
  for (std::size_t i = 0; i < page.size(); ++i) {
    out.push_back(intent::features_at(measures, i, config.context));
  }
  return out;
}

} // namespace penshape
