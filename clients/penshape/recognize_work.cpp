// The per-stroke work of `penshape recognize`: inks, grouping, timing.
#include "recognize_work.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "penshape/core/ink.hpp"
#include "penshape/core/intent_grouper.hpp"
#include "recognize_intent.hpp"

namespace penshape::cli {
namespace {

[[noreturn]] void refuse(const FileStroke& s, const std::string& what) {
  throw StrokeFileError(s.file + ":" + std::to_string(s.line) + ": " + what);
}

// The stroke's ink polygon (radius R, or R (0.25 + 0.75 p) with pressure: ink.hpp's curve with
// its default min_fraction and gamma) and the pen radius the clean shape is drawn with: R, or
// with pressure the median of the samples' radii. Nothing when the stroke has no size (the
// recognizer then names the problem).
std::optional<InkPolygon> ink_of(const FileStroke& s, const RecognizerConfig& config, bool pressure,
                                 double& pen_radius) {
  const ToleranceChoice tol = choose_tolerance(s.points, config);
  if (!(tol.pen_radius > 0) || !std::isfinite(tol.pen_radius)) return std::nullopt;
  InkOptions options;
  options.radius_mm = tol.pen_radius;
  std::vector<InkSample> samples;
  std::vector<double> radii;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    double radius = tol.pen_radius;
    if (pressure) {
      const double p = std::pow(s.pressure[i], options.gamma);
      radius *= options.min_fraction + (1.0 - options.min_fraction) * p;
    }
    samples.push_back({s.points[i].x, s.points[i].y, radius});
    radii.push_back(radius);
  }
  std::nth_element(radii.begin(), radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2),
                   radii.end());
  pen_radius = pressure ? radii[radii.size() / 2] : tol.pen_radius;
  return ink_polygon(samples, options);
}

} // namespace

std::vector<RecognizeRow> recognize_batch(const std::vector<FileStroke>& batch,
                                          const RecognizeOptions& options) {
  const std::vector<IntentDecision> intents = intents_of(batch);
  IntentGrouper grouper(options.grouping, options.recognizer, options.snap_writing);
  std::vector<double> seconds;
  for (std::size_t k = 0; k < batch.size(); ++k) {
    const FileStroke& s = batch[k];
    if (options.pressure && s.pressure.empty()) refuse(s, "--pressure: the stroke has no pressure");
    const auto t0 = std::chrono::steady_clock::now();
    StrokeInput input;
    input.samples = s.points;
    std::optional<InkPolygon> ink;
    try {
      // Writing is never recognized (unless --snap-writing): no ink to build for it.
      if (options.on_ink && (options.snap_writing || intents[k].intent == Intent::kDrawing)) {
        ink = ink_of(s, options.recognizer, options.pressure, input.pen_radius);
        if (ink) input.ink = &*ink;
      }
      grouper.add(input, intents[k].intent);
    } catch (const InvalidInput& e) {
      refuse(s, e.what());
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::vector<RecognizeRow> rows;
  for (GroupedShape& g : grouper.shapes()) {
    RecognizeRow row;
    for (const std::size_t i : g.strokes) {
      row.strokes.push_back(&batch[i]);
      row.seconds += seconds[i];
    }
    row.intent = intent_of_answer(intents, g.strokes);
    row.shape = std::move(g);
    rows.push_back(std::move(row));
  }
  return rows;
}

} // namespace penshape::cli
