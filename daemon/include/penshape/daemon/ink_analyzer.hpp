#pragma once
#include <memory>

#include "penshape/daemon/stroke_analyzer.hpp"

namespace penshape::daemon {

// Ink polygons with the core's penshape::ink_polygon (pen radius from the settings); no shapes.
// Compiled with PENSHAPE_DAEMON_WITH_ENGINE.
std::shared_ptr<StrokeAnalyzer> make_ink_analyzer();

} // namespace penshape::daemon
