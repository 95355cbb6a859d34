#include "penshape/daemon/geometry_backend.hpp"

namespace penshape::daemon {

v1::CurvedRegion GeometryBackend::offset_boundary(const PolygonSet& /*p*/,
                                                  const Rational& /*radius*/,
                                                  const CancelHook& /*cancel*/) {
  throw NotAvailable(
      "include_offset: this server's geometry backend cannot compute offset boundaries with arcs");
}

} // namespace penshape::daemon
