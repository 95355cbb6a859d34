#pragma once
// The sample sources and engines this build contains. The drivers' device manager and recording
// replay plug in here (make_device_source, make_replay_source), the recognizer's stroke analyzer in
// make_stroke_analyzer, the deconstruction engine in make_geometry_backend.
#include <memory>
#include <string>

#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"

namespace penshape::daemon {

// The tablets attached to this machine (hotplug included); null when this build has no device
// manager.
std::shared_ptr<SampleSource> make_device_source();
// A recording replayed as if live; throws NotAvailable when this build cannot replay, and
// std::runtime_error when the file cannot be read.
std::shared_ptr<SampleSource> make_replay_source(const std::string& path);
// Null when the ink-polygon engine and recognizer are not linked.
std::shared_ptr<StrokeAnalyzer> make_stroke_analyzer();
// Null when the deconstruction engine is not linked.
std::shared_ptr<GeometryBackend> make_geometry_backend();

} // namespace penshape::daemon
