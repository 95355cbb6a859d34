// offset(P, r) with true arcs: a fine round-joined Clipper offset, whose arc vertices are then
// regrouped into circular arcs around P's vertices (see arc_offset.hpp).
#include "penshape/core/arc_offset.hpp"

#include <clipper.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>

#include "penshape/core/deconstruct.hpp"

namespace penshape {
namespace {

using ClipperLib::cInt;
using ClipperLib::Path;
using ClipperLib::Paths;

struct CellHash {
  std::size_t operator()(const std::pair<long long, long long>& c) const {
    return std::hash<long long>()(c.first * 1'000'003LL ^ c.second);
  }
};

// P's vertices in a hash grid of cell size r, to find the centre of an arc vertex quickly.
class VertexIndex {
 public:
  VertexIndex(const std::vector<PointD>& vertices, double cell) : vertices_(vertices), cell_(cell) {
    for (std::size_t i = 0; i < vertices.size(); ++i) cells_[key(vertices[i])].push_back(i);
  }
  // The vertex at distance r ± tol from p, or -1.
  long find(PointD p, double r, double tol) const {
    const auto [cx, cy] = key(p);
    for (long long dx = -1; dx <= 1; ++dx) {
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find({cx + dx, cy + dy});
        if (it == cells_.end()) continue;
        for (std::size_t i : it->second) {
          const double d = std::hypot(p.x - vertices_[i].x, p.y - vertices_[i].y);
          if (std::abs(d - r) <= tol) return static_cast<long>(i);
        }
      }
    }
    return -1;
  }

 private:
  std::pair<long long, long long> key(PointD p) const {
    return {static_cast<long long>(std::floor(p.x / cell_)),
            static_cast<long long>(std::floor(p.y / cell_))};
  }
  const std::vector<PointD>& vertices_;
  double cell_;
  std::unordered_map<std::pair<long long, long long>, std::vector<std::size_t>, CellHash> cells_;
};

CurveRing curves_of(const Path& path, double grid, double r, double tol, const VertexIndex& index,
                    const std::vector<PointD>& vertices) {
  const std::size_t n = path.size();
  std::vector<PointD> pts(n);
  std::vector<long> center(n);
  for (std::size_t i = 0; i < n; ++i) {
    pts[i] = {static_cast<double>(path[i].X) * grid, static_cast<double>(path[i].Y) * grid};
    center[i] = index.find(pts[i], r, tol);
  }
  CurveRing ring;
  // Start at a vertex where a run of equal centres begins, so no arc wraps around the start.
  std::size_t start = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (center[i] < 0 || center[(i + n - 1) % n] != center[i]) {
      start = i;
      break;
    }
  }
  std::size_t i = 0;
  while (i < n) {
    const std::size_t a = (start + i) % n;
    std::size_t len = 1; // vertices a, a+1, ... sharing a's centre
    while (center[a] >= 0 && len < n && center[(a + len) % n] == center[a]) ++len;
    if (len >= 2) {
      const std::size_t b = (a + len - 1) % n;
      ring.curves.push_back({BoundaryCurve::Kind::kArc, pts[a], pts[b],
                             vertices[static_cast<std::size_t>(center[a])], r});
      i += len - 1;
    }
    const std::size_t from = (start + i) % n;
    const std::size_t to = (from + 1) % n;
    if (i < n) ring.curves.push_back({BoundaryCurve::Kind::kSegment, pts[from], pts[to], {}, 0.0});
    ++i;
  }
  return ring;
}

void collect(const ClipperLib::PolyNode& node, double grid, double r, double tol,
             const VertexIndex& index, const std::vector<PointD>& vertices, CurvedRegion& out) {
  CurvedPolygon polygon;
  polygon.outer = curves_of(node.Contour, grid, r, tol, index, vertices);
  for (const ClipperLib::PolyNode* hole : node.Childs) {
    polygon.holes.push_back(curves_of(hole->Contour, grid, r, tol, index, vertices));
    for (const ClipperLib::PolyNode* island : hole->Childs) {
      collect(*island, grid, r, tol, index, vertices, out);
    }
  }
  out.polygons.push_back(std::move(polygon));
}

// A ring of zero area (fewer than three vertices, or a walk there and back such as [a, p, b, p])
// is a curve, the degenerate solution simplification returns for a thin stroke: its offset is
// the offset of the chain of its edges (round ends), not of a region.
bool is_curve(const Ring& ring) { return ring.size() < 3 || sgn(twice_signed_area(ring)) == 0; }

} // namespace

CurvedRegion offset_with_arcs(const PolygonSet& p, double r, double max_error) {
  if (!(r > 0) || !std::isfinite(r))
    throw InvalidInput("the offset radius must be positive and finite");
  if (max_error == 0.0) max_error = r / 1000;
  if (!(max_error > 0) || !std::isfinite(max_error) || max_error > r) {
    throw InvalidInput("the arc offset error must be positive, finite and at most the radius");
  }
  PolygonSet oriented; // the polygons with area; curves go to `curves`
  std::vector<const Ring*> curves;
  for (const PolygonWithHoles& poly : p.polygons) {
    if (!poly.outer.empty() && is_curve(poly.outer)) {
      if (!poly.holes.empty()) throw InvalidInput("a polygon of zero area cannot have holes");
      curves.push_back(&poly.outer);
    } else {
      oriented.polygons.push_back(poly);
    }
  }
  if (!oriented.polygons.empty() || curves.empty()) validate_region(oriented);
  normalize_orientation(oriented);

  // Grid: three roundings of half a diagonal take at most a quarter of the error; Clipper's
  // arcs (sagitta <= 2.25 times its tolerance) the rest before they are regrouped.
  const double grid = std::ldexp(
      1.0, static_cast<int>(std::floor(std::log2(max_error / 4 / (1.5 * std::numbers::sqrt2)))));
  std::vector<PointD> vertices;
  Paths rings;
  double extent = r;
  auto to_path = [&](const Ring& ring) {
    Path path;
    for (const auto& v : ring) {
      const PointD d = to_double(v);
      vertices.push_back(d);
      extent = std::max({extent, std::abs(d.x) + r, std::abs(d.y) + r});
      path.push_back({static_cast<cInt>(std::llround(d.x / grid)),
                      static_cast<cInt>(std::llround(d.y / grid))});
    }
    return path;
  };
  for (const auto& poly : oriented.polygons) {
    rings.push_back(to_path(poly.outer));
    for (const auto& h : poly.holes) rings.push_back(to_path(h));
  }
  Paths chains; // each curve walked once round, back to its start
  for (const Ring* curve : curves) {
    Path chain = to_path(*curve);
    chain.push_back(chain.front());
    chains.push_back(std::move(chain));
  }
  if (extent / grid > 1e18) throw InvalidInput("coordinates too large for the requested arc error");

  ClipperLib::ClipperOffset offsetter;
  offsetter.ArcTolerance = (max_error * 3 / 4 / 2.25) / grid;
  offsetter.AddPaths(rings, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  offsetter.AddPaths(chains, ClipperLib::jtRound, ClipperLib::etOpenRound);
  Paths grown;
  offsetter.Execute(grown, r / grid);
  ClipperLib::Clipper clipper;
  clipper.StrictlySimple(true);
  clipper.AddPaths(grown, ClipperLib::ptSubject, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);

  CurvedRegion out;
  out.max_error = max_error;
  const VertexIndex index(vertices, r);
  // An offset vertex of an arc lies at r from its centre up to the rounding (2 grid steps).
  const double tol = 2 * grid;
  for (const ClipperLib::PolyNode* node : tree.Childs) {
    collect(*node, grid, r, tol, index, vertices, out);
  }
  // Clipper's outer rings are counterclockwise and holes clockwise in its y-up sense already.
  return out;
}

} // namespace penshape
