#include "clipper_stage.hpp"

#include "douglas_peucker.hpp"
#include "raw_offset.hpp"
#include "stripe_union.hpp"

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

// A hole node read as the outer ring of a polygon whose holes are the node's islands; the
// islands' own holes are polygons again (the inverted reading of collect()).
void collect_hole_as_outer(const cl::PolyNode& hole, IRegion& out) {
  IPolygon poly;
  poly.outer = to_ring(hole.Contour);
  if (twice_area(poly.outer) < 0) std::reverse(poly.outer.begin(), poly.outer.end());
  for (const cl::PolyNode* island : hole.Childs) {
    IRing h = to_ring(island->Contour);
    if (twice_area(h) > 0) std::reverse(h.begin(), h.end());
    poly.holes.push_back(std::move(h));
    for (const cl::PolyNode* inner : island->Childs) collect_hole_as_outer(*inner, out);
  }
  IRings one{std::move(poly.outer)};
  clean_rings(one);
  if (one.empty()) return;
  poly.outer = std::move(one.front());
  clean_rings(poly.holes);
  out.push_back(std::move(poly));
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

namespace {
OffsetMode g_offset_mode = OffsetMode::kStriped;
} // namespace

void set_offset_mode(OffsetMode mode) { g_offset_mode = mode; }
OffsetMode offset_mode() { return g_offset_mode; }

double round_join_steps(double delta, double arc_tolerance) {
  if (delta > 0.0 || g_offset_mode == OffsetMode::kStriped) {
    const double a = std::fabs(delta);
    return std::numbers::pi / std::acos(std::max(-1.0, 1.0 - arc_tolerance / a));
  }
  const double y = std::min(arc_tolerance / kJoinDepthFactor, std::fabs(delta) * 0.25);
  return std::numbers::pi / std::acos(1.0 - y / std::fabs(delta));
}

namespace {

IRegion offset_outward(const IRings& rings, double delta, double arc_tolerance, Spokes spokes) {
  cl::PolyTree tree;
  if (g_offset_mode == OffsetMode::kStriped) {
    union_positive(raw_outward(rings, delta, arc_tolerance, spokes), tree);
  } else {
    cl::Clipper c;
    c.AddPaths(raw_outward(rings, delta, arc_tolerance, Spokes::kKeep), cl::ptSubject, true);
    c.Execute(cl::ctUnion, tree, cl::pftPositive, cl::pftPositive);
  }
  IRegion out;
  collect(tree, out);
  return out;
}

// Inset by d = |delta|: the complement (within a box d + 2 units wider than the rings) offset
// outwards by d; the inset is what that offset leaves of the box: the box's holes, with the
// islands in them as their holes (and the islands' holes as polygons again).
IRegion offset_inward(const IRings& rings, double d, double arc_tolerance, Spokes spokes) {
  IRings complement;
  complement.reserve(rings.size() + 1);
  cl::cInt x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool first = true;
  for (const IRing& ring : rings) {
    for (const IPt& p : ring) {
      x0 = first ? p.x : std::min<cl::cInt>(x0, p.x);
      y0 = first ? p.y : std::min<cl::cInt>(y0, p.y);
      x1 = first ? p.x : std::max<cl::cInt>(x1, p.x);
      y1 = first ? p.y : std::max<cl::cInt>(y1, p.y);
      first = false;
    }
  }
  if (first) return {};
  const auto m = static_cast<cl::cInt>(std::ceil(d)) + 2;
  complement.push_back({{x0 - m, y0 - m}, {x1 + m, y0 - m}, {x1 + m, y1 + m}, {x0 - m, y1 + m}});
  for (const IRing& ring : rings) complement.emplace_back(ring.rbegin(), ring.rend());
  cl::PolyTree tree;
  union_positive(raw_outward(complement, d, arc_tolerance, spokes), tree);
  IRegion out;
  for (const cl::PolyNode* box : tree.Childs) {
    for (const cl::PolyNode* hole : box->Childs) collect_hole_as_outer(*hole, out);
  }
  return out;
}

} // namespace

IRegion offset_round(const IRings& rings, double delta, double arc_tolerance, Spokes spokes) {
  if (delta > 0.0) return offset_outward(rings, delta, arc_tolerance, spokes);
  if (g_offset_mode == OffsetMode::kStriped) {
    return offset_inward(rings, -delta, arc_tolerance, spokes);
  }
  cl::ClipperOffset offset(2.0, arc_tolerance / kJoinDepthFactor);
  offset.AddPaths(to_paths(rings), cl::jtRound, cl::etClosedPolygon);
  cl::PolyTree tree;
  offset.Execute(tree, delta);
  IRegion out;
  collect(tree, out);
  return out;
}

namespace {

// The Boolean operation on the paths added to `c` (positive winding for both), as a region.
IRegion execute(cl::Clipper& c, cl::ClipType type) {
  cl::PolyTree tree;
  c.Execute(type, tree, cl::pftPositive, cl::pftPositive);
  IRegion out;
  collect(tree, out);
  return out;
}

} // namespace

IRegion difference(const IRings& subject, const IRings& clip) {
  cl::Clipper c;
  c.AddPaths(to_paths(subject), cl::ptSubject, true);
  c.AddPaths(to_paths(clip), cl::ptClip, true);
  return execute(c, cl::ctDifference);
}

IRegion simplify(const IRings& input, double tolerance) {
  IRings rings;
  for (const IRing& ring : input) rings.push_back(simplify_ring(ring, tolerance));
  clean_rings(rings);
  cl::Clipper c;
  c.AddPaths(to_paths(rings), cl::ptSubject, true);
  c.StrictlySimple(true);
  return execute(c, cl::ctUnion);
}

IRegion simplify_rings_only(const IRegion& region, double tolerance) {
  IRegion out;
  out.reserve(region.size());
  for (const IPolygon& poly : region) {
    IRings outer{simplify_ring(poly.outer, tolerance)};
    clean_rings(outer);
    if (outer.empty()) continue;
    IPolygon p{std::move(outer.front()), {}};
    for (const IRing& hole : poly.holes) p.holes.push_back(simplify_ring(hole, tolerance));
    clean_rings(p.holes);
    out.push_back(std::move(p));
  }
  return out;
}

} // namespace penshape::fast
