#pragma once
// Writing or drawing: the intent of every stroke of a page, so that handwriting is never snapped
// to shapes. A pure function of the page's strokes in drawing order (no I/O, no threads, no
// CGAL): each stroke is measured (size, turning, straightness, speed) and set against its
// context, the strokes drawn just before and after it (the page's typical writing height,
// neighbours on a text line, the run of small strokes it sits in). A small model (8 tanh units, a
// logistic output) whose weights were learned offline (scripts/intent_learn.py, committed as
// core/src/intent/intent_weights.hpp) turns that into P(writing).
//
// Not a certificate: this is a classifier, and its score is a probability estimate. It decides
// only whether the recognizer is asked at all; every snap is still certified.
//
// Live use (a tablet, a StreamSamples stream, a SubmitStroke group_key): pass the recent strokes
// and the new one as the page and read the last decision; the context is then the strokes
// before it only.
#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape {

enum class Intent { kWriting, kDrawing };

std::string_view to_string(Intent intent); // "writing" | "drawing"

struct IntentConfig {
  // Millimetres per unit of the samples (the model knows how big letters are in mm).
  double mm_per_unit = 1.0;
  // Strokes before and after a stroke (in drawing order) that form its context.
  std::size_t context = 24;
  // P(writing) at or above which a stroke is writing.
  double writing_threshold = 0.5;
};

struct IntentDecision {
  Intent intent = Intent::kDrawing;
  double writing_score = 0.0; // P(writing) in [0, 1]
};

// The measures the model weighs, per stroke (scripts/intent_learn.py reads them).
inline constexpr std::size_t kIntentFeatureCount = 21;
using IntentFeatures = std::array<double, kIntentFeatureCount>;
// Their names, in order (the columns of `intent_bench --features`).
const std::array<std::string_view, kIntentFeatureCount>& intent_feature_names();

// One stroke as the decision sees it: its samples in order (t in seconds, or all 0 when the
// stroke is not timed). A stroke with one distinct point (a dot) is a writing mark, never an
// error; an empty stroke is a dot too.
using IntentStroke = std::span<const StrokePoint>;

// Throws InvalidInput (deconstruct.hpp) when a coordinate or time is not finite or a setting is
// out of range (mm_per_unit <= 0, threshold outside [0, 1]).
std::vector<IntentFeatures> intent_features(std::span<const IntentStroke> page,
                                            const IntentConfig& config = {});
// One decision per stroke of the page, in the page's order.
std::vector<IntentDecision> decide_intent(std::span<const IntentStroke> page,
                                          const IntentConfig& config = {});
// The same, for strokes held as vectors.
std::vector<IntentDecision> decide_intent(const std::vector<std::vector<StrokePoint>>& page,
                                          const IntentConfig& config = {});

namespace intent {
struct StrokeMeasures;
}

// Live use without measuring the recent strokes again for every new one: add() gives what
// decide_intent(the last `context` strokes, then this one).back() gives, and the stroke then
// joins the context; remember() lets a stroke join without a decision. Copies share the
// (immutable) measures.
class LiveIntent {
 public:
  // Throws InvalidInput for the settings decide_intent refuses.
  explicit LiveIntent(const IntentConfig& config = {});
  // Throws InvalidInput as decide_intent does (the stroke then does not join the context).
  IntentDecision add(IntentStroke stroke);
  void remember(IntentStroke stroke);

 private:
  void join(std::shared_ptr<const intent::StrokeMeasures> measures);
  IntentConfig config_;
  std::vector<std::shared_ptr<const intent::StrokeMeasures>> recent_; // oldest first
};

} // namespace penshape
