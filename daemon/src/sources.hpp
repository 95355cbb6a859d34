#pragma once
// The engines this build links, for penshaped's main: the deconstruction engine in
// make_geometry_backend, the recognizer's stroke analyzer in make_stroke_analyzer. (The sample
// source is the drivers' DeviceManager, device_manager_source.hpp.)
#include <memory>

#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"

namespace penshape::daemon {

// Null when the ink-polygon engine and recognizer are not linked.
std::shared_ptr<StrokeAnalyzer> make_stroke_analyzer();
// Null when the deconstruction engine is not linked.
std::shared_ptr<GeometryBackend> make_geometry_backend();

} // namespace penshape::daemon
