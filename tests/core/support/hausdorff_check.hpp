#pragma once
// An independent Hausdorff check for tests: no CGAL, no engine code, only doubles.
//
// hausdorff_to_offset(S, r, Q, h) estimates H(offset(S, r), Q) for a skeleton S (a polygonal
// region, or open polylines such as a pen stroke) and a region Q by dense sampling:
//   - Q side: every grid point (spacing h) inside Q and samples every h along ∂Q, each at
//     distance max(0, d(x, S) - r) from offset(S, r);
//   - offset side: every grid point with d(g, S) <= r + h (a slight superset of offset(S, r))
//     and points at distance exactly r around samples of S's edges, each at distance d(y, Q).
// Both distance functions are 1-Lipschitz and every point of either set lies within 1.25·h of a
// sample (h/sqrt(2) to the grid, or h/sqrt(2) to the boundary plus h/2 along it), so the true
// value satisfies  estimate - 1.25·h <= H <= estimate + 1.25·h  (HausdorffEstimate::error).
#include <vector>

#include "penshape/core/polygon_set.hpp"

namespace penshape::test {

struct RegionD {
  std::vector<std::vector<PointD>> rings; // closed rings; inside = odd number of rings around
};

struct SkeletonD {
  std::vector<std::vector<PointD>> closed_rings; // a region (its interior belongs to S)
  std::vector<std::vector<PointD>> polylines;    // open chains (a single point is allowed)
};

RegionD to_region_d(const PolygonSet& set);
SkeletonD region_skeleton(const PolygonSet& set);

struct HausdorffEstimate {
  double value = 0.0; // the sampled estimate
  double error = 0.0; // |true - value| <= error
};

HausdorffEstimate hausdorff_to_offset(const SkeletonD& s, double r, const RegionD& q,
                                      double spacing);

// Distance from p to the region (0 inside).
double distance_to_region(const RegionD& q, PointD p);

} // namespace penshape::test
