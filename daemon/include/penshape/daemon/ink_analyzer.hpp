#pragma once
#include <memory>

#include "penshape/core/ink.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"

namespace penshape::daemon {

// How the daemon draws a stroke's ink: one radius, the settings' pen radius (PenSettings has no
// pressure curve yet; with one, InkOptions::use_pressure would follow it here). Both analyzers
// use it, so the ink they report is the same.
InkOptions ink_options_for(const PenSettings& settings);

// The start of every analysis: the stroke's ink (ink_options_for), also set as
// `analysis->ink_polygon`. Throws Cancelled when `cancel` asks for it once the ink is drawn.
InkPolygon analyze_ink(const Stroke& stroke, const PenSettings& settings, const CancelHook& cancel,
                       StrokeAnalysis* analysis);

// Ink polygons with the core's penshape::ink_polygon (ink_options_for); no shapes. The daemon
// runs the recognizing analyzer (recognizing_analyzer.hpp); this one serves builds and tests that
// want the ink alone. Compiled with PENSHAPE_DAEMON_WITH_ENGINE.
std::shared_ptr<StrokeAnalyzer> make_ink_analyzer();

} // namespace penshape::daemon
