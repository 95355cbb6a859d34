// The one CGAL translation unit for exact regions: Minkowski sums (reduced convolution) and
// Boolean set operations on Epeck. Keep CGAL here (BUILD-NOTES: ~30 s per such TU).
#include "geometry/exact_region.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <algorithm>
#include <iterator>
#include <type_traits>
#include <vector>

namespace penshape::detail {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Exact = CGAL::Epeck_ft; // the exact number type behind Epeck's lazy numbers
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHolesCgal = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSetCgal = CGAL::Polygon_set_2<Kernel>;

void check_cancel(const CancelHook& cancel) {
  if (cancel && cancel()) throw Cancelled();
}

// CGAL uses gmpxx when available (CGAL_USE_GMPXX): Epeck's exact numbers are our Rationals.
static_assert(std::is_same_v<Exact, Rational>, "CGAL must be built with gmpxx (CGAL_USE_GMPXX)");

FT to_ft(const Rational& q) { return FT(q); }

Rational to_rational(const FT& v) { return CGAL::exact(v); }

Polygon to_cgal(const Ring& ring) {
  Polygon p;
  for (const auto& v : ring) p.push_back(Point(to_ft(v.x), to_ft(v.y)));
  return p;
}

Ring to_ring(const Polygon& p) {
  Ring ring;
  ring.reserve(p.size());
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) {
    ring.push_back({to_rational(it->x()), to_rational(it->y())});
  }
  return ring;
}

std::vector<PolygonWithHolesCgal> pieces(const PolygonSetCgal& set) {
  std::vector<PolygonWithHolesCgal> out;
  out.reserve(set.number_of_polygons_with_holes());
  set.polygons_with_holes(std::back_inserter(out));
  return out;
}

PolygonSetCgal sum_all(const std::vector<PolygonWithHolesCgal>& parts, const Polygon& k,
                       const CancelHook& cancel) {
  std::vector<PolygonWithHolesCgal> sums;
  sums.reserve(parts.size());
  for (const auto& part : parts) {
    check_cancel(cancel);
    sums.push_back(CGAL::minkowski_sum_2(part, k));
  }
  check_cancel(cancel);
  PolygonSetCgal result;
  if (!sums.empty()) result.join(sums.begin(), sums.end());
  return result;
}

} // namespace

struct ExactRegion::Impl {
  PolygonSetCgal set;
};

ExactRegion::ExactRegion() : impl_(std::make_unique<Impl>()) {}
ExactRegion::~ExactRegion() = default;
ExactRegion::ExactRegion(ExactRegion&&) noexcept = default;
ExactRegion& ExactRegion::operator=(ExactRegion&&) noexcept = default;

ExactRegion ExactRegion::from(const PolygonSet& set) {
  ExactRegion r;
  std::vector<PolygonWithHolesCgal> parts;
  parts.reserve(set.polygons.size());
  for (const auto& p : set.polygons) {
    std::vector<Polygon> holes;
    holes.reserve(p.holes.size());
    for (const auto& h : p.holes) holes.push_back(to_cgal(h));
    parts.emplace_back(to_cgal(p.outer), holes.begin(), holes.end());
  }
  // The polygons are disjoint (validated), so a plain insertion suffices.
  r.impl_->set.insert(parts.begin(), parts.end());
  return r;
}

PolygonSet ExactRegion::to_polygon_set() const {
  PolygonSet out;
  for (const auto& pwh : pieces(impl_->set)) {
    PolygonWithHoles p;
    p.outer = to_ring(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) p.holes.push_back(to_ring(*h));
    out.polygons.push_back(std::move(p));
  }
  return out;
}

bool ExactRegion::empty() const { return impl_->set.is_empty(); }

std::size_t ExactRegion::vertex_count() const {
  std::size_t n = 0;
  for (const auto& pwh : pieces(impl_->set)) {
    n += pwh.outer_boundary().size();
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) n += h->size();
  }
  return n;
}

ExactRegion ExactRegion::minkowski_sum(const Ring& convex, const CancelHook& cancel) const {
  ExactRegion r;
  r.impl_->set = sum_all(pieces(impl_->set), to_cgal(convex), cancel);
  return r;
}

ExactRegion ExactRegion::inset(const Ring& convex, const CancelHook& cancel) const {
  ExactRegion r;
  if (impl_->set.is_empty()) return r;
  // Bounding box of X, widened by more than the reach of K.
  const std::vector<PolygonWithHolesCgal> parts = pieces(impl_->set);
  CGAL::Bbox_2 box = parts.front().outer_boundary().bbox();
  for (const auto& p : parts) box += p.outer_boundary().bbox();
  Rational reach = 0;
  for (const auto& v : convex) reach = std::max({reach, Rational(abs(v.x)), Rational(abs(v.y))});
  const Rational margin = 2 * reach + 1;
  const FT x0 = to_ft(exact(box.xmin()) - margin);
  const FT y0 = to_ft(exact(box.ymin()) - margin);
  const FT x1 = to_ft(exact(box.xmax()) + margin);
  const FT y1 = to_ft(exact(box.ymax()) + margin);
  Polygon frame;
  frame.push_back(Point(x0, y0));
  frame.push_back(Point(x1, y0));
  frame.push_back(Point(x1, y1));
  frame.push_back(Point(x0, y1));
  PolygonSetCgal outside(frame);
  outside.difference(impl_->set);
  check_cancel(cancel);
  const PolygonSetCgal grown = sum_all(pieces(outside), to_cgal(convex), cancel);
  r.impl_->set = impl_->set;
  r.impl_->set.difference(grown);
  return r;
}

bool ExactRegion::contains(const ExactRegion& other) const {
  PolygonSetCgal rest = other.impl_->set;
  rest.difference(impl_->set);
  return rest.is_empty();
}

ExactRegion ExactRegion::minus(const ExactRegion& other) const {
  ExactRegion r;
  r.impl_->set = impl_->set;
  r.impl_->set.difference(other.impl_->set);
  return r;
}

} // namespace penshape::detail
