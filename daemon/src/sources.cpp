#include "sources.hpp"

namespace penshape::daemon {

// The recognizer (annulus fits) plugs in here: an adapter implementing StrokeAnalyzer.
std::shared_ptr<StrokeAnalyzer> make_stroke_analyzer() { return nullptr; }

std::shared_ptr<GeometryBackend> make_geometry_backend() {
#ifdef PENSHAPE_DAEMON_WITH_ENGINE
  return make_core_geometry_backend();
#else
  return nullptr;
#endif
}

} // namespace penshape::daemon
