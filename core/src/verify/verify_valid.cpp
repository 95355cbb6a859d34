// Validity of a claimed solution region (verify_valid.hpp): a sweep over x-sorted edges with
// exact segment tests, then nesting by exact point-in-ring tests.
#include "verify/verify_valid.hpp"

#include <CGAL/FPU.h>

#include <algorithm>
#include <vector>

#include "verify/verify_kernel.hpp"

namespace penshape::verify {
namespace {

struct RingInfo {
  std::size_t polygon;
  std::size_t hole; // 0: the outer ring, k: hole k - 1
  std::vector<VPoint> points;
  bool degenerate = false; // zero area: an open polyline
};

std::string where(const RingInfo& r, std::size_t vertex) {
  std::string s = "polygon " + std::to_string(r.polygon) + ", ";
  s += r.hole == 0 ? "outer ring" : "hole " + std::to_string(r.hole - 1);
  return s + ", vertex " + std::to_string(vertex);
}

// p strictly inside the ring by the even-odd rule (p not on the ring).
bool inside_ring(const VPoint& p, const std::vector<VPoint>& ring) {
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (crosses_ray(ring[i], ring[(i + 1) % ring.size()], p)) inside = !inside;
  }
  return inside;
}

struct EdgeRef {
  std::size_t ring;
  std::size_t index;
  double xmin, xmax, ymin, ymax;
};

// Adjacent edges (a, b) and (b, c) of one ring fold back when c lies on the ray from b through a.
bool folds_back(const VPoint& a, const VPoint& b, const VPoint& c) {
  if (orientation(a, b, c) != 0) return false;
  return sgn((a.e.x - b.e.x) * (c.e.x - b.e.x) + (a.e.y - b.e.y) * (c.e.y - b.e.y)) > 0;
}

std::optional<std::string> crossing_problem(const std::vector<RingInfo>& rings) {
  std::vector<EdgeRef> edges;
  double magnitude = 0;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const auto& pts = rings[k].points;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const VPoint& a = pts[i];
      const VPoint& b = pts[(i + 1) % pts.size()];
      edges.push_back({k, i, std::min(a.x.inf(), b.x.inf()), std::max(a.x.sup(), b.x.sup()),
                       std::min(a.y.inf(), b.y.inf()), std::max(a.y.sup(), b.y.sup())});
      magnitude = std::max({magnitude, std::abs(a.x.inf()), std::abs(a.x.sup()),
                            std::abs(a.y.inf()), std::abs(a.y.sup())});
    }
  }
  // Interval bounds already enclose the exact coordinates; the pad only guards the comparisons.
  const double pad = 1e-12 * magnitude;
  std::sort(edges.begin(), edges.end(),
            [](const EdgeRef& u, const EdgeRef& v) { return u.xmin < v.xmin; });
  std::vector<const EdgeRef*> active;
  for (const EdgeRef& e : edges) {
    std::erase_if(active, [&](const EdgeRef* o) { return o->xmax + pad < e.xmin; });
    const RingInfo& re = rings[e.ring];
    const std::size_t n = re.points.size();
    const VPoint& a = re.points[e.index];
    const VPoint& b = re.points[(e.index + 1) % n];
    for (const EdgeRef* o : active) {
      if (o->ymax + pad < e.ymin || e.ymax + pad < o->ymin) continue;
      const RingInfo& ro = rings[o->ring];
      const VPoint& c = ro.points[o->index];
      const VPoint& d = ro.points[(o->index + 1) % ro.points.size()];
      if (o->ring == e.ring) {
        if (re.degenerate) continue;
        if ((o->index + 1) % n == e.index) {
          if (folds_back(c, d, b)) return where(re, e.index) + ": the ring folds back on itself";
          continue;
        }
        if ((e.index + 1) % n == o->index) {
          if (folds_back(a, b, d)) return where(re, o->index) + ": the ring folds back on itself";
          continue;
        }
        if (segments_meet(a, b, c, d)) {
          return where(re, e.index) + ": the ring touches itself (edge " +
                 std::to_string(o->index) + ")";
        }
      } else if (segments_meet(a, b, c, d)) {
        return where(re, e.index) + ": the ring meets " + where(ro, o->index);
      }
    }
    active.push_back(&e);
  }
  return std::nullopt;
}

std::optional<std::string> nesting_problem(const PolygonSet& set,
                                           const std::vector<RingInfo>& rings) {
  // Rings in order: polygon by polygon, outer ring first.
  std::vector<std::size_t> outer_of(set.polygons.size());
  for (std::size_t k = 0; k < rings.size(); ++k) {
    if (rings[k].hole == 0) outer_of[rings[k].polygon] = k;
  }
  for (const RingInfo& r : rings) {
    const VPoint& v = r.points.front();
    const RingInfo& outer = rings[outer_of[r.polygon]];
    if (r.hole > 0) {
      if (r.degenerate) return where(r, 0) + ": a hole of zero area";
      if (outer.degenerate || !inside_ring(v, outer.points)) {
        return where(r, 0) + ": the hole is not inside its outer ring";
      }
      for (const RingInfo& s : rings) {
        if (&s != &r && s.polygon == r.polygon && s.hole > 0 && inside_ring(v, s.points)) {
          return where(r, 0) + ": the hole lies inside another hole";
        }
      }
      continue;
    }
    if (r.degenerate) continue;
    for (const RingInfo& s : rings) {
      if (s.polygon == r.polygon || s.degenerate || !inside_ring(v, s.points)) continue;
      // Inside s: fine only when s is a hole (then its own outer ring contains it too, and the
      // parity over that polygon's rings is even).
      bool in_region = false;
      for (const RingInfo& t : rings) {
        if (t.polygon == s.polygon && inside_ring(v, t.points)) in_region = !in_region;
      }
      if (in_region)
        return where(r, 0) + ": the polygon lies inside polygon " + std::to_string(s.polygon);
    }
  }
  return std::nullopt;
}

// v0 ... vm ... v1 with v(m+k) = v(m-k): the polyline v0 ... vm, there and back.
bool traces_back(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n % 2 != 0) return false;
  const std::size_t m = n / 2;
  for (std::size_t k = 1; k < m; ++k) {
    if (!(ring[m + k] == ring[m - k])) return false;
  }
  return true;
}

} // namespace

std::optional<std::string> region_problem(const PolygonSet& set) {
  const CGAL::Protect_FPU_rounding<true> rounding;
  std::vector<RingInfo> rings;
  for (std::size_t k = 0; k < set.polygons.size(); ++k) {
    const auto& poly = set.polygons[k];
    for (std::size_t h = 0; h <= poly.holes.size(); ++h) {
      const Ring& ring = h == 0 ? poly.outer : poly.holes[h - 1];
      RingInfo info{k, h, {}, sgn(twice_signed_area(ring)) == 0};
      for (const auto& p : ring) info.points.push_back(vpoint(p));
      if (ring.size() < 2) return where(info, 0) + ": fewer than 2 vertices";
      if (info.degenerate && !traces_back(ring)) {
        return where(info, 0) + ": zero area without being a polyline traced back and forth";
      }
      for (std::size_t i = 0; i < ring.size(); ++i) {
        if (ring[i] == ring[(i + 1) % ring.size()]) {
          return where(info, i) + ": repeated vertex";
        }
      }
      rings.push_back(std::move(info));
    }
  }
  if (auto p = crossing_problem(rings)) return p;
  return nesting_problem(set, rings);
}

} // namespace penshape::verify
