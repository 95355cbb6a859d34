// The stripe-by-stripe union and the offsets built on it (clipper_stage.hpp) against brute-force
// checks written here: winding numbers of the raw paths, point-in-region of the results and
// exact point-to-segment distances, at random points away from every boundary (Clipper and the
// stripe crossings round to the grid by up to a unit).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "engine/fast/clipper_stage.hpp"
#include "engine/fast/stripe_union.hpp"

namespace {

namespace cl = ClipperLib;
using penshape::fast::IPolygon;
using penshape::fast::IRegion;
using penshape::fast::IRing;
using penshape::fast::IRings;

struct P {
  double x, y;
};

double segment_distance(P p, P a, P b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::fmax(0.0, std::fmin(1.0, t));
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

template <class Ring, class Get>
double ring_distance(P p, const Ring& ring, Get get) {
  double best = INFINITY;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    best = std::fmin(best, segment_distance(p, get(ring[i]), get(ring[(i + 1) % ring.size()])));
  }
  return best;
}

// Winding number of a closed path around p (p off the path).
template <class Ring, class Get>
int winding(P p, const Ring& ring, Get get) {
  int w = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const P a = get(ring[i]), b = get(ring[(i + 1) % ring.size()]);
    const double cross = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
    if (a.y <= p.y && b.y > p.y && cross > 0) ++w;
    if (b.y <= p.y && a.y > p.y && cross < 0) --w;
  }
  return w;
}

P of_cl(const cl::IntPoint& q) { return {static_cast<double>(q.X), static_cast<double>(q.Y)}; }
P of_ipt(const penshape::fast::IPt& q) {
  return {static_cast<double>(q.x), static_cast<double>(q.y)};
}

bool in_region(P p, const IRegion& region) {
  int w = 0;
  for (const IPolygon& poly : region) {
    w += winding(p, poly.outer, of_ipt);
    for (const IRing& h : poly.holes) w += winding(p, h, of_ipt);
  }
  return w > 0;
}

double region_distance(P p, const IRings& rings) {
  double best = INFINITY;
  for (const IRing& r : rings) best = std::fmin(best, ring_distance(p, r, of_ipt));
  return best;
}

// Random self-overlapping closed paths: jagged loops around a few centres.
cl::Paths random_paths(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  cl::Paths paths;
  for (int k = 0; k < 3; ++k) {
    const double cx = 200 + 600 * u(rng), cy = 200 + 600 * u(rng);
    cl::Path path;
    const int n = 40 + static_cast<int>(160 * u(rng));
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n * (u(rng) < 0.1 ? -1 : 1);
      const double r = 80 + 150 * u(rng);
      path.emplace_back(std::llround(cx + r * std::cos(a)), std::llround(cy + r * std::sin(a)));
    }
    if (u(rng) < 0.3) std::reverse(path.begin(), path.end());
    paths.push_back(std::move(path));
  }
  return paths;
}

IRegion region_of(const cl::PolyTree& tree) {
  IRegion out;
  for (cl::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
    IRing ring;
    for (const auto& q : node->Contour) ring.push_back({q.X, q.Y});
    // Outers and holes alike: the winding sum of Clipper's oriented output is the region.
    out.push_back({ring, {}});
  }
  return out;
}

TEST(StripeUnion, StripedUnionIsThePositiveWindingRegion) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> coord(0.0, 1000.0);
  for (int trial = 0; trial < 20; ++trial) {
    const cl::Paths paths = random_paths(rng);
    cl::PolyTree striped;
    penshape::fast::union_positive(paths, striped, 16); // many thin stripes
    const IRegion region = region_of(striped);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
      const P p{coord(rng) + 0.25, coord(rng) + 0.25};
      double near = INFINITY;
      int w = 0;
      for (const cl::Path& path : paths) {
        near = std::fmin(near, ring_distance(p, path, of_cl));
        w += winding(p, path, of_cl);
      }
      if (near < 2.0) continue; // rounding of the crossings and of Clipper
      ++checked;
      ASSERT_EQ(in_region(p, region), w > 0) << "trial " << trial << " at " << p.x << ", " << p.y;
    }
    EXPECT_GT(checked, 1000);
  }
}

// The stripes must not leave zero-width bridges along their lines: a square with a square hole
// cut into several stripes comes back as one outer ring with one hole of the right areas (the
// insets read the region from exactly this structure).
TEST(StripeUnion, StripesKeepHolesAsHoles) {
  const cl::Paths paths{{{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}},
                        {{300, 300}, {300, 700}, {700, 700}, {700, 300}}};
  for (const std::size_t stripe_vertices : {std::size_t{1}, std::size_t{2}, std::size_t{3}}) {
    cl::PolyTree tree;
    penshape::fast::union_positive(paths, tree, stripe_vertices);
    ASSERT_EQ(tree.ChildCount(), 1) << stripe_vertices;
    const cl::PolyNode& outer = *tree.Childs[0];
    EXPECT_DOUBLE_EQ(cl::Area(outer.Contour), 1e6);
    ASSERT_EQ(outer.ChildCount(), 1) << stripe_vertices;
    EXPECT_DOUBLE_EQ(cl::Area(outer.Childs[0]->Contour), -160000.0);
  }
}

// Paths wider than tall are turned a quarter turn for Clipper's sweep and the result turned
// back: the same positive-winding region (with stripes and without, turning on and off), and a
// wide square ring with a hole keeps its structure and its place.
TEST(StripeUnion, WidePathsTurnedForTheSweepGiveTheSameRegion) {
  std::mt19937 rng(26);
  std::uniform_real_distribution<double> coord(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    cl::Paths paths = random_paths(rng);
    for (cl::Path& path : paths) {
      for (cl::IntPoint& q : path) q.X *= 5; // five times wider than tall
    }
    for (const bool turn : {true, false}) {
      for (const std::size_t stripe_vertices : {std::size_t{64}, std::size_t{1} << 20}) {
        penshape::fast::set_turn_wide_paths(turn);
        cl::PolyTree tree;
        penshape::fast::union_positive(paths, tree, stripe_vertices);
        penshape::fast::set_turn_wide_paths(true);
        const IRegion region = region_of(tree);
        int checked = 0;
        for (int i = 0; i < 1500; ++i) {
          const P p{5000.0 * coord(rng) + 0.25, 1000.0 * coord(rng) + 0.25};
          double near = INFINITY;
          int w = 0;
          for (const cl::Path& path : paths) {
            near = std::fmin(near, ring_distance(p, path, of_cl));
            w += winding(p, path, of_cl);
          }
          if (near < 2.0) continue;
          ++checked;
          ASSERT_EQ(in_region(p, region), w > 0)
              << "trial " << trial << " turn " << turn << " at " << p.x << ", " << p.y;
        }
        EXPECT_GT(checked, 1000);
      }
    }
  }
  const cl::Paths framed{{{0, 0}, {4000, 0}, {4000, 1000}, {0, 1000}},
                         {{300, 300}, {300, 700}, {3700, 700}, {3700, 300}}};
  cl::PolyTree tree;
  penshape::fast::union_positive(framed, tree);
  ASSERT_EQ(tree.ChildCount(), 1);
  const cl::PolyNode& outer = *tree.Childs[0];
  EXPECT_DOUBLE_EQ(cl::Area(outer.Contour), 4e6);
  for (const cl::IntPoint& q : outer.Contour) {
    EXPECT_TRUE((q.X == 0 || q.X == 4000) && (q.Y == 0 || q.Y == 1000)) << q.X << ", " << q.Y;
  }
  ASSERT_EQ(outer.ChildCount(), 1);
  EXPECT_DOUBLE_EQ(cl::Area(outer.Childs[0]->Contour), -3400.0 * 400.0);
}

TEST(StripeUnion, ClampKeepsWindingStrictlyInsideTheStripe) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(0.0, 1000.0);
  const cl::Paths paths = random_paths(rng);
  const cl::Paths clamped = penshape::fast::clamp_to_stripe(paths, 400, 600);
  for (const cl::Path& path : clamped) {
    for (const auto& q : path) {
      EXPECT_GE(q.X, 400);
      EXPECT_LE(q.X, 600);
    }
  }
  for (int i = 0; i < 3000; ++i) {
    const P p{402 + 196 * coord(rng) / 1000, coord(rng)};
    double near = INFINITY;
    int w = 0, wc = 0;
    for (const cl::Path& path : paths) {
      near = std::fmin(near, ring_distance(p, path, of_cl));
      w += winding(p, path, of_cl);
    }
    for (const cl::Path& path : clamped) wc += winding(p, path, of_cl);
    if (near < 1.0) continue;
    ASSERT_EQ(w, wc) << p.x << ", " << p.y;
  }
}

// A jagged star with a hole: offsets and insets in both modes within their stated bounds
// (offset(|d| - tol) ⊆ R ⊆ offset(|d|), the same for insets), checked by distances.
IRings jagged_region() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> bump(0.0, 60.0);
  IRing outer;
  const int n = 3000; // over the stripes' threshold
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    const double r = 3000 + 400 * std::sin(5 * a) + bump(rng);
    outer.push_back({std::llround(5000 + r * std::cos(a)), std::llround(5000 + r * std::sin(a))});
  }
  IRing hole{{4800, 4800}, {4800, 5300}, {5100, 5300}, {5100, 4800}}; // clockwise
  return {outer, hole};
}

bool in_rings(P p, const IRings& rings) {
  int w = 0;
  for (const IRing& r : rings) w += winding(p, r, of_ipt);
  return w > 0;
}

void check_offset(const IRings& rings, double delta, double tol) {
  const IRegion result = penshape::fast::offset_round(rings, delta, tol);
  ASSERT_FALSE(result.empty());
  std::mt19937 rng(static_cast<unsigned>(std::llround(std::fabs(delta)) * 2 + (delta < 0 ? 1 : 0)));
  std::uniform_real_distribution<double> coord(0.0, 10000.0);
  const double d = std::fabs(delta);
  int inside = 0, outside = 0;
  for (int i = 0; i < 4000; ++i) {
    const P p{coord(rng) + 0.3, coord(rng) + 0.3};
    const bool in_q = in_rings(p, rings);
    // Signed distance to the boundary: inside the offset/inset exactly when...
    const double dist = region_distance(p, rings);
    const bool in_r = in_region(p, result);
    if (delta > 0) {
      if (in_q || dist < d - tol - 2) {
        ASSERT_TRUE(in_r) << "missing " << p.x << ", " << p.y;
        ++inside;
      } else if (dist > d + 2) {
        ASSERT_FALSE(in_r) << "extra " << p.x << ", " << p.y;
        ++outside;
      }
    } else {
      if (in_q && dist > d + 2) {
        ASSERT_TRUE(in_r) << "missing " << p.x << ", " << p.y;
        ++inside;
      } else if (!in_q || dist < d - tol - 2) {
        ASSERT_FALSE(in_r) << "extra " << p.x << ", " << p.y;
        ++outside;
      }
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

TEST(StripeUnion, OffsetsAndInsetsStayWithinTheirBoundsInBothModes) {
  const IRings rings = jagged_region();
  for (const auto mode :
       {penshape::fast::OffsetMode::kStriped, penshape::fast::OffsetMode::kFormer}) {
    penshape::fast::set_offset_mode(mode);
    for (const double delta : {150.0, 700.0, -150.0, -700.0}) {
      SCOPED_TRACE(delta);
      check_offset(rings, delta, 40.0);
    }
  }
  penshape::fast::set_offset_mode(penshape::fast::OffsetMode::kStriped);
}

} // namespace
