#include "region_convert.hpp"

namespace penshape::fast {

PolygonSet to_polygon_set(const GridFrame& frame, const IRegion& region) {
  PolygonSet out;
  for (const IPolygon& poly : region) {
    PolygonWithHoles pw;
    for (const IPt& p : poly.outer) pw.outer.push_back(frame.exact(p));
    for (const IRing& hole : poly.holes) {
      Ring h;
      for (const IPt& p : hole) h.push_back(frame.exact(p));
      pw.holes.push_back(std::move(h));
    }
    out.polygons.push_back(std::move(pw));
  }
  return out;
}

IRegion to_grid(const GridFrame& frame, const PolygonSet& set) {
  IRegion out;
  for (const auto& poly : set.polygons) {
    IPolygon ip;
    for (const auto& p : poly.outer) ip.outer.push_back(frame.round(p));
    for (const auto& h : poly.holes) {
      IRing ih;
      for (const auto& p : h) ih.push_back(frame.round(p));
      ip.holes.push_back(std::move(ih));
    }
    out.push_back(std::move(ip));
  }
  return out;
}

} // namespace penshape::fast
