// The ink-only stroke analyzer: StrokeAnalysis::shape stays SHAPE_KIND_UNSPECIFIED, so no
// ShapeRecognized is published.
#include "penshape/daemon/ink_analyzer.hpp"

#include "penshape/core/ink.hpp"
#include "penshape/daemon/proto_convert.hpp"

namespace penshape::daemon {
namespace {

class InkAnalyzer final : public StrokeAnalyzer {
 public:
  StrokeAnalysis analyze(const Stroke& stroke, const PenSettings& settings,
                         const CancelHook& cancel) override {
    StrokeAnalysis analysis;
    analyze_ink(stroke, settings, cancel, &analysis);
    return analysis;
  }
};

} // namespace

InkOptions ink_options_for(const PenSettings& settings) {
  InkOptions options;
  options.radius_mm = settings.pen_radius_mm;
  return options;
}

InkPolygon analyze_ink(const Stroke& stroke, const PenSettings& settings, const CancelHook& cancel,
                       StrokeAnalysis* analysis) {
  InkPolygon ink = ink_polygon(stroke, ink_options_for(settings));
  if (cancel && cancel()) throw Cancelled();
  to_proto(ink.region, &analysis->ink_polygon);
  return ink;
}

std::shared_ptr<StrokeAnalyzer> make_ink_analyzer() { return std::make_shared<InkAnalyzer>(); }

} // namespace penshape::daemon
