#include "clipper_stage.hpp"

#include "douglas_peucker.hpp"

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

} // namespace

IRings flatten(const IRegion& region) {
  IRings rings;
  for (const IPolygon& p : region) {
    rings.push_back(p.outer);
    rings.insert(rings.end(), p.holes.begin(), p.holes.end());
  }
  return rings;
}

// Clipper rounds the number of steps of each join to the nearest integer, so one chord can span
// up to 1.5 nominal steps: its depth is then up to 1.5² = 2.25 times the ArcTolerance it was
// given. Asking for tolerance / kJoinDepthFactor keeps every chord within `tolerance`.
constexpr double kJoinDepthFactor = 2.5;

double round_join_steps(double delta, double arc_tolerance) {
  const double y = std::min(arc_tolerance / kJoinDepthFactor, std::fabs(delta) * 0.25);
  return std::numbers::pi / std::acos(1.0 - y / std::fabs(delta));
}

IRegion offset_round(const IRings& rings, double delta, double arc_tolerance) {
  cl::ClipperOffset offset(2.0, arc_tolerance / kJoinDepthFactor);
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

IRegion simplify(const IRings& input, double tolerance) {
  IRings rings;
  for (const IRing& ring : input) rings.push_back(simplify_ring(ring, tolerance));
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
