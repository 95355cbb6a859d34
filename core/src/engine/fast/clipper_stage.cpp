#include "clipper_stage.hpp"

#include <clipper.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace penshape::fast {
namespace {

namespace cl = ClipperLib;

cl::Paths to_paths(const IRings& rings) {
  cl::Paths paths;
  paths.reserve(rings.size());
  for (const IRing& ring : rings) {
    cl::Path path;
    path.reserve(ring.size());
    for (const IPt& p : ring) path.emplace_back(p.x, p.y);
    paths.push_back(std::move(path));
  }
  return paths;
}

IRing to_ring(const cl::Path& path) {
  IRing ring;
  ring.reserve(path.size());
  for (const auto& p : path) ring.push_back({p.X, p.Y});
  return ring;
}

// Outer contours with their holes; islands inside holes become polygons of their own.
void collect(const cl::PolyNode& node, IRegion& out) {
  for (const cl::PolyNode* outer : node.Childs) {
    IPolygon poly;
    poly.outer = to_ring(outer->Contour);
    if (twice_area(poly.outer) < 0) std::reverse(poly.outer.begin(), poly.outer.end());
    for (const cl::PolyNode* hole : outer->Childs) {
      IRing h = to_ring(hole->Contour);
      if (twice_area(h) > 0) std::reverse(h.begin(), h.end());
      poly.holes.push_back(std::move(h));
      collect(*hole, out);
    }
    IRings one{poly.outer};
    clean_rings(one);
    if (one.empty()) continue;
    poly.outer = std::move(one.front());
    clean_rings(poly.holes);
    out.push_back(std::move(poly));
  }
}

// Perpendicular-distance Douglas-Peucker on the open chain ring[i..j] (indices modulo n).
void douglas_peucker(const IRing& ring, std::size_t i, std::size_t j, double tol,
                     std::vector<char>& keep) {
  const std::size_t n = ring.size();
  if ((j + n - i) % n < 2) return;
  const DPt a = to_d(ring[i % n]);
  const DPt b = to_d(ring[j % n]);
  double worst = -1.0;
  std::size_t worst_k = i;
  for (std::size_t k = i + 1; k < j; ++k) {
    const double d = point_segment_distance(to_d(ring[k % n]), a, b);
    if (d > worst) {
      worst = d;
      worst_k = k;
    }
  }
  if (worst > tol) {
    keep[worst_k % n] = 1;
    douglas_peucker(ring, i, worst_k, tol, keep);
    douglas_peucker(ring, worst_k, j, tol, keep);
  }
}

IRing simplify_ring(const IRing& ring, double tol) {
  const std::size_t n = ring.size();
  if (n <= 4) return ring;
  // Split the closed ring at vertex 0 and at the vertex farthest from it.
  std::size_t far = 0;
  std::int64_t best = -1;
  for (std::size_t k = 1; k < n; ++k) {
    const std::int64_t dx = ring[k].x - ring[0].x, dy = ring[k].y - ring[0].y;
    const std::int64_t d = std::max(std::abs(dx), std::abs(dy));
    if (d > best) {
      best = d;
      far = k;
    }
  }
  std::vector<char> keep(n, 0);
  keep[0] = keep[far] = 1;
  douglas_peucker(ring, 0, far, tol, keep);
  douglas_peucker(ring, far, n, tol, keep);
  IRing out;
  for (std::size_t k = 0; k < n; ++k) {
    if (keep[k]) out.push_back(ring[k]);
  }
  return out;
}

} // namespace

IRings flatten(const IRegion& region) {
  IRings rings;
  for (const IPolygon& p : region) {
    rings.push_back(p.outer);
    rings.insert(rings.end(), p.holes.begin(), p.holes.end());
  }
  return rings;
}

double round_join_steps(double delta, double arc_tolerance) {
  const double y = std::min(arc_tolerance, std::fabs(delta) * 0.25);
  return std::numbers::pi / std::acos(1.0 - y / std::fabs(delta));
}

IRegion offset_round(const IRings& rings, double delta, double arc_tolerance) {
  cl::ClipperOffset offset(2.0, arc_tolerance);
  offset.AddPaths(to_paths(rings), cl::jtRound, cl::etClosedPolygon);
  cl::PolyTree tree;
  offset.Execute(tree, delta);
  IRegion out;
  collect(tree, out);
  return out;
}

IRegion difference(const IRings& subject, const IRings& clip) {
  cl::Clipper c;
  c.AddPaths(to_paths(subject), cl::ptSubject, true);
  c.AddPaths(to_paths(clip), cl::ptClip, true);
  cl::PolyTree tree;
  c.Execute(cl::ctDifference, tree, cl::pftPositive, cl::pftPositive);
  IRegion out;
  collect(tree, out);
  return out;
}

IRegion simplify(const IRegion& region, double tolerance) {
  IRings rings;
  for (const IRing& ring : flatten(region)) rings.push_back(simplify_ring(ring, tolerance));
  clean_rings(rings);
  cl::Clipper c;
  c.AddPaths(to_paths(rings), cl::ptSubject, true);
  cl::PolyTree tree;
  c.StrictlySimple(true);
  c.Execute(cl::ctUnion, tree, cl::pftPositive, cl::pftPositive);
  IRegion out;
  collect(tree, out);
  return out;
}

} // namespace penshape::fast
