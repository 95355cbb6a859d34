#include "sources.hpp"

namespace penshape::daemon {

// The drivers branch provides the device manager (per-device reader threads, segmenter); until it
// is merged this build serves the API without devices.
std::shared_ptr<SampleSource> make_device_source() { return nullptr; }

std::shared_ptr<SampleSource> make_replay_source(const std::string& path) {
  throw NotAvailable("--replay " + path +
                     ": this build has no recording reader (the drivers' hid-recorder replay)");
}

std::shared_ptr<StrokeAnalyzer> make_stroke_analyzer() { return nullptr; }

std::shared_ptr<GeometryBackend> make_geometry_backend() {
#ifdef PENSHAPE_DAEMON_WITH_ENGINE
  return make_core_geometry_backend();
#else
  return nullptr;
#endif
}

} // namespace penshape::daemon
