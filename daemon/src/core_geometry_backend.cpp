// The Geometry service's backend on the core library's engines. Compiled only when the engine is
// linked (PENSHAPE_DAEMON_WITH_ENGINE), because penshape::deconstruct() lives in core/src/engine.
#include "penshape/daemon/geometry_backend.hpp"

namespace penshape::daemon {
namespace {

class CoreGeometryBackend final : public GeometryBackend {
 public:
  DeconstructResult deconstruct(const PolygonSet& q, const DeconstructParams& params,
                                const CancelHook& cancel,
                                const DeconstructLimits& limits) override {
    return penshape::deconstruct(q, params, cancel, limits);
  }
};

} // namespace

std::unique_ptr<GeometryBackend> make_core_geometry_backend() {
  return std::make_unique<CoreGeometryBackend>();
}

} // namespace penshape::daemon
