// validate_deconstruct_input: the checks that make Q a valid polygonal region for the engines,
// with messages that name polygon, ring and vertex.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "deconstruct/validate_input.hpp"
#include "geometry/exact_predicates.hpp"
#include "geometry/ring_nesting.hpp"
#include "geometry/segment_sweep.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/disk_approximation.hpp"
#include "penshape/core/validated_region.hpp"

namespace penshape {
namespace {

using detail::FilteredPoint;

struct RingRef {
  std::size_t polygon = 0;
  int hole = -1; // -1: the outer ring
  const Ring* ring = nullptr;
  std::vector<FilteredPoint> points;
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
};

std::string ring_name(const RingRef& r) {
  std::string s = "polygon " + std::to_string(r.polygon) + ", ";
  s += r.hole < 0 ? std::string("outer ring") : "hole " + std::to_string(r.hole);
  return s;
}

std::string point_text(const ExactPoint& p) {
  std::ostringstream os;
  os.precision(17);
  os << '(' << p.x.get_d() << ", " << p.y.get_d() << ')';
  return os.str();
}

std::string edge_name(const RingRef& r, std::size_t i) {
  const std::size_t j = (i + 1) % r.ring->size();
  return ring_name(r) + ", edge " + std::to_string(i) + "-" + std::to_string(j) + " from " +
         point_text((*r.ring)[i]) + " to " + point_text((*r.ring)[j]);
}

// The index after i in a ring of n vertices: a compare, not `%` (a division per vertex in each
// of the O(n) loops below, a measurable share of validating a large ring).
std::size_t next_index(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }

// Widens a double interval so it surely contains the exact values it was rounded from.
double widen_down(double v) { return v - 1e-15 * std::abs(v) - std::numeric_limits<double>::min(); }
double widen_up(double v) { return v + 1e-15 * std::abs(v) + std::numeric_limits<double>::min(); }

// The shoelace sum in doubles decides most rings without GMP: each term carries a relative
// error of a few ulps (conversion and product), so 1e-12 · Σ|terms| bounds the total error.
bool surely_nonzero_area(const std::vector<FilteredPoint>& ring) {
  double sum = 0;
  double magnitude = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const FilteredPoint& a = ring[i];
    const FilteredPoint& b = ring[next_index(i, ring.size())];
    const double t1 = a.x * b.y;
    const double t2 = a.y * b.x;
    sum += t1 - t2;
    magnitude += std::abs(t1) + std::abs(t2);
  }
  // Far from underflow only: subnormal products lose the relative error bound.
  return std::isfinite(sum) && std::isfinite(magnitude) && magnitude > 1e-250 &&
         std::abs(sum) > 1e-12 * magnitude * static_cast<double>(ring.size());
}

void check_ring_basics(const RingRef& r) {
  const Ring& ring = *r.ring;
  if (ring.size() < 3) {
    throw InvalidInput(ring_name(r) + " has " + std::to_string(ring.size()) +
                       " vertices; a ring needs at least 3");
  }
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const std::size_t j = next_index(i, ring.size());
    // Distinct doubles mean distinct points (rounding is monotone): GMP only on a tie.
    const FilteredPoint& a = r.points[i];
    const FilteredPoint& b = r.points[j];
    if (a.x == b.x && a.y == b.y && ring[i] == ring[j]) {
      throw InvalidInput(ring_name(r) + ": vertex " + std::to_string(j) + " repeats vertex " +
                         std::to_string(i) + " at " + point_text(ring[i]));
    }
  }
  if (!surely_nonzero_area(r.points) && sgn(twice_signed_area(ring)) == 0) {
    throw InvalidInput(ring_name(r) + " has zero area");
  }
}

// Two edges of one ring that share a vertex only touch there unless they fold back on each
// other (a spike), which makes the ring non-simple.
bool adjacent_edges_overlap(const RingRef& r, std::size_t first, std::size_t second) {
  // first ends where second starts: a = start of first, b = shared vertex, c = end of second.
  const std::size_t n = r.ring->size();
  const FilteredPoint& a = r.points[first];
  const FilteredPoint& b = r.points[next_index(first, n)];
  const FilteredPoint& c = r.points[next_index(second, n)];
  if (detail::orientation(a, b, c) != 0) return false;
  return detail::on_collinear_segment(*a.exact, *b.exact, *c.exact) ||
         detail::on_collinear_segment(*b.exact, *c.exact, *a.exact);
}

// O(n): every pair of consecutive edges, to name a fold-back as such (the sweep below would
// report it, or another contact, as a touch).
void check_no_fold_backs(const std::vector<RingRef>& rings) {
  for (const RingRef& r : rings) {
    const std::size_t n = r.ring->size();
    for (std::size_t i = 0; i < n; ++i) {
      if (adjacent_edges_overlap(r, i, next_index(i, n))) {
        throw InvalidInput(ring_name(r) + " is self-intersecting: edges " + edge_name(r, i) +
                           " and " + std::to_string((i + 1) % n) + " fold back on each other");
      }
    }
  }
}

// Shamos–Hoey over every edge of every ring: O(n log n) exact predicates, one event per vertex.
// The fold-back check runs only once the sweep found a contact, with the same messages as when
// it ran first: the sweep returns nothing only when no two edges share a forbidden point
// (segment_sweep.hpp), and two consecutive edges that fold back share more than their common
// vertex, so without a contact there is no fold-back to name; with one, the fold-back check
// names a fold-back before the contact is reported, as it did when it ran first. Valid input,
// the common case, skips its n orientations (the sweep tests each vertex's two edges anyway).
void check_no_crossings(const std::vector<RingRef>& rings, const CancelHook& cancel) {
  std::vector<std::span<const FilteredPoint>> points;
  points.reserve(rings.size());
  for (const RingRef& r : rings) points.emplace_back(r.points);
  const auto contact = detail::find_ring_contact(points, cancel);
  if (!contact) return;
  check_no_fold_backs(rings);
  const auto& [a, e] = *contact;
  const RingRef& ra = rings[a.ring];
  const RingRef& re = rings[e.ring];
  const std::string what = a.ring == e.ring ? ring_name(ra) + " is self-intersecting: "
                                            : std::string("rings intersect: ");
  throw InvalidInput(what + edge_name(ra, a.index) + " touches or crosses " +
                     edge_name(re, e.index));
}

// Strictly inside (the rings are known not to touch, so "on the boundary" cannot happen for a
// vertex of another ring).
bool inside(const RingRef& r, const FilteredPoint& p) {
  if (p.x < r.xmin || p.x > r.xmax || p.y < r.ymin || p.y > r.ymax) return false;
  const auto& pts = r.points;
  bool in = false;
  for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    const ExactPoint& a = *pts[i].exact;
    const ExactPoint& b = *pts[j].exact;
    if ((a.y > p.exact->y) != (b.y > p.exact->y)) {
      // Crossing of the horizontal ray to the right: orientation of (b, a, p) vs direction.
      const int o = detail::orientation(pts[j], pts[i], p);
      if ((b.y < a.y) ? o > 0 : o < 0) in = !in;
    }
  }
  return in;
}

// The pairwise test below, O(n · rings): run only to name the fault once the sweep found one.
void name_nesting_fault(const std::vector<RingRef>& rings, const PolygonSet& q) {
  // rings are ordered polygon by polygon, outer first.
  std::vector<std::size_t> outer_of(q.polygons.size());
  std::vector<std::vector<std::size_t>> holes_of(q.polygons.size());
  for (std::size_t k = 0; k < rings.size(); ++k) {
    if (rings[k].hole < 0) {
      outer_of[rings[k].polygon] = k;
    } else {
      holes_of[rings[k].polygon].push_back(k);
    }
  }
  for (std::size_t p = 0; p < q.polygons.size(); ++p) {
    const RingRef& outer = rings[outer_of[p]];
    for (std::size_t h : holes_of[p]) {
      if (!inside(outer, rings[h].points[0])) {
        throw InvalidInput(ring_name(rings[h]) + " lies outside its outer ring");
      }
      for (std::size_t g : holes_of[p]) {
        if (g != h && inside(rings[g], rings[h].points[0])) {
          throw InvalidInput(ring_name(rings[h]) + " lies inside " + ring_name(rings[g]) +
                             " (holes overlap)");
        }
      }
    }
  }
  for (std::size_t p = 0; p < q.polygons.size(); ++p) {
    for (std::size_t o = 0; o < q.polygons.size(); ++o) {
      if (o == p) continue;
      const FilteredPoint& v = rings[outer_of[o]].points[0];
      if (!inside(rings[outer_of[p]], v)) continue;
      const bool in_a_hole = std::any_of(holes_of[p].begin(), holes_of[p].end(),
                                         [&](std::size_t h) { return inside(rings[h], v); });
      if (!in_a_hole) {
        throw InvalidInput("polygon " + std::to_string(o) + " overlaps polygon " +
                           std::to_string(p) + " (polygons of a set must be disjoint)");
      }
    }
  }
}

// With disjoint boundaries, the region is well nested exactly when every hole's innermost
// container is its own outer ring and every outer ring's is a hole or nothing (then a polygon
// inside another lies in one of its holes, and no hole lies in another hole of its polygon).
// The containers come from one O(n log n) sweep (geometry/ring_nesting).
void check_nesting(const std::vector<RingRef>& rings, const PolygonSet& q) {
  if (rings.size() < 2) return; // one outer ring: nothing can be nested wrongly
  std::vector<std::vector<FilteredPoint>> points;
  points.reserve(rings.size());
  std::vector<std::size_t> outer_of(q.polygons.size());
  for (std::size_t k = 0; k < rings.size(); ++k) {
    points.push_back(rings[k].points);
    if (rings[k].hole < 0) outer_of[rings[k].polygon] = k;
  }
  const std::vector<long> parent = detail::ring_parents(points);
  bool ok = true;
  for (std::size_t k = 0; k < rings.size() && ok; ++k) {
    if (rings[k].hole >= 0) {
      ok = parent[k] == static_cast<long>(outer_of[rings[k].polygon]);
    } else {
      ok = parent[k] < 0 || rings[static_cast<std::size_t>(parent[k])].hole >= 0;
    }
  }
  if (ok) return;
  name_nesting_fault(rings, q);
  throw InvalidInput("rings are nested inconsistently"); // not reached: the faults coincide
}

} // namespace

void detail::check_vertex_limit(const PolygonSet& q, std::size_t max_vertices) {
  const std::size_t n = q.vertex_count();
  if (n > max_vertices) {
    throw InvalidInput("the region has " + std::to_string(n) + " vertices, over the limit of " +
                       std::to_string(max_vertices));
  }
}

void validate_region(const PolygonSet& q, std::size_t max_vertices, const CancelHook& cancel) {
  if (q.empty()) throw InvalidInput("the region is empty (no polygons)");
  detail::check_vertex_limit(q, max_vertices);
  std::vector<RingRef> rings;
  for (std::size_t p = 0; p < q.polygons.size(); ++p) {
    rings.push_back({p, -1, &q.polygons[p].outer, {}, 0, 0, 0, 0});
    for (std::size_t h = 0; h < q.polygons[p].holes.size(); ++h) {
      rings.push_back({p, static_cast<int>(h), &q.polygons[p].holes[h], {}, 0, 0, 0, 0});
    }
  }
  for (RingRef& r : rings) {
    r.points.reserve(r.ring->size());
    for (const auto& v : *r.ring) r.points.push_back(detail::filtered(v));
    check_ring_basics(r); // on the doubles converted once above, with exact ties
    r.xmin = r.ymin = std::numeric_limits<double>::infinity();
    r.xmax = r.ymax = -std::numeric_limits<double>::infinity();
    for (const auto& v : r.points) {
      r.xmin = std::min(r.xmin, widen_down(v.x));
      r.xmax = std::max(r.xmax, widen_up(v.x));
      r.ymin = std::min(r.ymin, widen_down(v.y));
      r.ymax = std::max(r.ymax, widen_up(v.y));
    }
  }
  check_no_crossings(rings, cancel); // and the fold-backs, when it finds a contact
  check_nesting(rings, q);
}

namespace detail {

bool is_valid_region(const PolygonSet& set) {
  if (set.empty()) return true;
  try {
    validate_region(set, std::numeric_limits<std::size_t>::max());
  } catch (const InvalidInput&) {
    return false;
  }
  return true;
}

} // namespace detail

void validate_deconstruct_params(const DeconstructParams& params, const DeconstructLimits& limits) {
  const Rational& r = params.radius;
  const Rational& eps = params.tolerance;
  const Rational& delta = params.precision;
  if (sgn(r) <= 0) throw InvalidInput("radius must be positive, got " + r.get_str());
  if (sgn(eps) <= 0) throw InvalidInput("tolerance must be positive, got " + eps.get_str());
  if (sgn(delta) <= 0) throw InvalidInput("precision must be positive, got " + delta.get_str());
  if (delta >= eps) {
    throw InvalidInput("precision must be smaller than the tolerance, got precision " +
                       delta.get_str() + " >= tolerance " + eps.get_str());
  }
  if (r > eps) {
    // The finest disk the engines build: D̄_{r+eps, r+eps+delta} (exterior, last offset).
    const Rational a = r + eps;
    const Rational b = a + delta;
    const std::size_t z = std::max<std::size_t>(disk_approximation_z(a, b), 2);
    if (z > limits.max_disk_vertices / 4) {
      throw InvalidInput(
          "precision " + std::to_string(delta.get_d()) + " is too fine for radius " +
          std::to_string(r.get_d()) + ": the disk approximation needs " +
          (z == static_cast<std::size_t>(-1) ? std::string("too many") : std::to_string(4 * z)) +
          " vertices, over the limit of " + std::to_string(limits.max_disk_vertices));
    }
  }
}

void validate_deconstruct_input(const PolygonSet& q, const DeconstructParams& params,
                                const DeconstructLimits& limits, const CancelHook& cancel) {
  validate_deconstruct_params(params, limits);
  validate_region(q, limits.max_input_vertices, cancel);
}

ValidatedRegion ValidatedRegion::validate(PolygonSet q, std::size_t max_vertices,
                                          const CancelHook& cancel) {
  validate_region(q, max_vertices, cancel);
  return ValidatedRegion(std::move(q));
}

} // namespace penshape
