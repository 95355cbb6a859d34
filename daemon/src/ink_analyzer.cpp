// The stroke analyzer this build has: the ink polygon from the core (penshape::ink_polygon). The
// recognizer (annulus fits) extends it with the shape; until then StrokeAnalysis::shape stays
// SHAPE_KIND_UNSPECIFIED and no ShapeRecognized is published.
#include "penshape/daemon/ink_analyzer.hpp"

#include "penshape/core/ink.hpp"
#include "penshape/daemon/proto_convert.hpp"

namespace penshape::daemon {
namespace {

class InkAnalyzer final : public StrokeAnalyzer {
 public:
  StrokeAnalysis analyze(const Stroke& stroke, const PenSettings& settings,
                         const CancelHook& cancel) override {
    InkOptions options;
    options.radius_mm = settings.pen_radius_mm;
    const InkPolygon ink = ink_polygon(stroke, options);
    if (cancel && cancel()) throw Cancelled();
    StrokeAnalysis analysis;
    to_proto(ink.region, &analysis.ink_polygon);
    return analysis;
  }
};

} // namespace

std::shared_ptr<StrokeAnalyzer> make_ink_analyzer() { return std::make_shared<InkAnalyzer>(); }

} // namespace penshape::daemon
