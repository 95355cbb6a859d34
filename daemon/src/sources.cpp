// The engines this build links, or none (sources.hpp).
#include "sources.hpp"

#include "penshape/daemon/ink_analyzer.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"

namespace penshape::daemon {

#ifdef PENSHAPE_DAEMON_WITH_ENGINE

// Ink polygons and certified shapes (recognizing_analyzer.cpp); deconstructions.
std::shared_ptr<StrokeAnalyzer> make_stroke_analyzer() { return make_recognizing_analyzer(); }
std::shared_ptr<GeometryBackend> make_geometry_backend() { return make_core_geometry_backend(); }

#else // built without the engine

std::shared_ptr<StrokeAnalyzer> make_stroke_analyzer() { return nullptr; }
std::shared_ptr<GeometryBackend> make_geometry_backend() { return nullptr; }

#endif

} // namespace penshape::daemon
