#include "sources.hpp"

#include "penshape/daemon/ink_analyzer.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"

namespace penshape::daemon {

// Ink polygons and certified shapes (recognizing_analyzer.cpp), with the engine built in.
std::shared_ptr<StrokeAnalyzer> make_stroke_analyzer() {
#ifdef PENSHAPE_DAEMON_WITH_ENGINE
  return make_recognizing_analyzer();
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
