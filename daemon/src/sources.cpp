#include "sources.hpp"

#include "penshape/daemon/ink_analyzer.hpp"

namespace penshape::daemon {

// The recognizer (annulus fits) plugs in here: an adapter implementing StrokeAnalyzer (ink
// polygon, shape, previews). Until then: ink polygons only.
std::shared_ptr<StrokeAnalyzer> make_stroke_analyzer() {
#ifdef PENSHAPE_DAEMON_WITH_ENGINE
  return make_ink_analyzer();
#else
  return nullptr;
#endif
}

std::shared_ptr<GeometryBackend> make_geometry_backend() {
#ifdef PENSHAPE_DAEMON_WITH_ENGINE
  return make_core_geometry_backend();
#else
  return nullptr;
#endif
}

} // namespace penshape::daemon
