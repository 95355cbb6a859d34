// The writing/drawing decision: the learned model (one hidden layer) over the page's features
// (intent.hpp; weights from scripts/intent_learn.py in intent_weights.hpp).
#include <cmath>
#include <memory>
#include <vector>

#include "intent_weights.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/intent.hpp"
#include "stroke_measures.hpp"

namespace penshape {
namespace {

// Features an untimed stroke cannot have (intent_features: timed, speed, pause): taken at their
// mean, so that missing timing counts for neither side.
constexpr std::size_t kTimed = 17;
constexpr bool is_timing(std::size_t k) { return k >= kTimed && k <= kTimed + 2; }

double writing_score(const IntentFeatures& f) {
  namespace w = intent::weights;
  const bool timed = f[kTimed] > 0.5;
  IntentFeatures z{};
  for (std::size_t k = 0; k < kIntentFeatureCount; ++k) {
    z[k] = !timed && is_timing(k) ? 0.0 : (f[k] - w::kMean[k]) / w::kScale[k];
  }
  double out = w::kOutputBias;
  for (std::size_t j = 0; j < w::kHidden; ++j) {
    double h = w::kHiddenBias[j];
    for (std::size_t k = 0; k < kIntentFeatureCount; ++k) h += w::kHiddenWeight[j][k] * z[k];
    out += w::kOutputWeight[j] * std::tanh(h);
  }
  return 1.0 / (1.0 + std::exp(-out));
}

// One distinct point (or none): an i-dot, a full stop, a decimal point.
bool is_dot(IntentStroke s) {
  for (const StrokePoint& p : s) {
    if (p.x != s.front().x || p.y != s.front().y) return false;
  }
  return true;
}

} // namespace

std::string_view to_string(Intent intent) {
  return intent == Intent::kWriting ? "writing" : "drawing";
}

std::vector<IntentDecision> decide_intent(std::span<const IntentStroke> page,
                                          const IntentConfig& config) {
  if (!(config.writing_threshold >= 0 && config.writing_threshold <= 1)) {
    throw InvalidInput("intent: writing_threshold must be in [0, 1]");
  }
  const std::vector<IntentFeatures> features = intent_features(page, config);
  std::vector<IntentDecision> out;
  out.reserve(page.size());
  for (std::size_t i = 0; i < page.size(); ++i) {
    const double score = is_dot(page[i]) ? 1.0 : writing_score(features[i]);
    out.push_back({score >= config.writing_threshold ? Intent::kWriting : Intent::kDrawing, score});
  }
  return out;
}

std::vector<IntentDecision> decide_intent(const std::vector<std::vector<StrokePoint>>& page,
                                          const IntentConfig& config) {
  const std::vector<IntentStroke> spans(page.begin(), page.end());
  return decide_intent(spans, config);
}

LiveIntent::LiveIntent(const IntentConfig& config) : config_(config) {
  if (!(config.writing_threshold >= 0 && config.writing_threshold <= 1)) {
    throw InvalidInput("intent: writing_threshold must be in [0, 1]");
  }
  if (!(config.mm_per_unit > 0) || !std::isfinite(config.mm_per_unit)) {
    throw InvalidInput("intent: mm_per_unit must be positive and finite");
  }
}

IntentDecision LiveIntent::add(IntentStroke stroke) {
  auto m = std::make_shared<const intent::StrokeMeasures>(
      intent::measure_stroke(stroke, config_.mm_per_unit));
  // The page decide_intent would see: the context's measures, then this stroke's.
  std::vector<intent::StrokeMeasures> page;
  page.reserve(recent_.size() + 1);
  for (const auto& r : recent_) page.push_back(*r);
  page.push_back(*m);
  const double score =
      is_dot(stroke) ? 1.0
                     : writing_score(intent::features_at(page, page.size() - 1, config_.context));
  join(std::move(m));
  return {score >= config_.writing_threshold ? Intent::kWriting : Intent::kDrawing, score};
}

void LiveIntent::remember(IntentStroke stroke) {
  join(std::make_shared<const intent::StrokeMeasures>(
      intent::measure_stroke(stroke, config_.mm_per_unit)));
}

void LiveIntent::join(std::shared_ptr<const intent::StrokeMeasures> measures) {
  recent_.push_back(std::move(measures));
  if (recent_.size() > config_.context) recent_.erase(recent_.begin());
}

} // namespace penshape
