// Grid regions to exact polygon sets and back (region_convert.hpp), ring by ring.
#include "region_convert.hpp"

namespace penshape::fast {
namespace {

// One ring through the frame, either way.
Ring exact_ring(const GridFrame& frame, const IRing& ring) {
  Ring out;
  out.reserve(ring.size());
  for (const IPt& p : ring) out.push_back(frame.exact(p));
  return out;
}

IRing grid_ring(const GridFrame& frame, const Ring& ring) {
  IRing out;
  out.reserve(ring.size());
  for (const ExactPoint& p : ring) out.push_back(frame.round(p));
  return out;
}

} // namespace

PolygonSet to_polygon_set(const GridFrame& frame, const IRegion& region) {
  PolygonSet out;
  for (const IPolygon& poly : region) {
    PolygonWithHoles pw{exact_ring(frame, poly.outer), {}};
    for (const IRing& hole : poly.holes) pw.holes.push_back(exact_ring(frame, hole));
    out.polygons.push_back(std::move(pw));
  }
  return out;
}

IRegion to_grid(const GridFrame& frame, const PolygonSet& set) {
  IRegion out;
  for (const auto& poly : set.polygons) {
    IPolygon ip{grid_ring(frame, poly.outer), {}};
    for (const Ring& hole : poly.holes) ip.holes.push_back(grid_ring(frame, hole));
    out.push_back(std::move(ip));
  }
  return out;
}

} // namespace penshape::fast
