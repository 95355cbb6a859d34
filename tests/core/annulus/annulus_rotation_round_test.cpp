// Translation + rotation with the round outer offset (and simple templates) against an
// independent oracle: angles sampled finely, each solved exactly under translation by the
// candidate enumeration of annulus_oracle.hpp. Sampling gives a lower bound on the max-cover and
// an upper bound on the minimum width; the certified answers must be consistent with both, and
// every covered set / placement is rechecked with the oracle's own distance code.
#include <gtest/gtest.h>

#include <numbers>

#include "annulus_oracle.hpp"
#include "penshape/core/annulus/rotation.hpp"

namespace penshape::annulus {
namespace {

constexpr int kAngles = 360;

oracle::Pose pose_of(const Placement& p) { return {p.tx, p.ty, p.theta}; }

double sample(int k) { return 2 * std::numbers::pi * k / kAngles; }

std::size_t oracle_cover(const std::vector<PointD>& poly, oracle::Kind kind, double delta,
                         const std::vector<PointD>& pts) {
  std::size_t best = 0;
  for (int k = 0; k < kAngles; ++k) {
    best = std::max(best, oracle::max_cover_translation(poly, kind, delta, pts, sample(k)));
  }
  return best;
}

// Smallest width over the sampled angles (an upper bound on the optimum).
double oracle_width(const std::vector<PointD>& poly, oracle::Kind kind,
                    const std::vector<PointD>& pts, double hi) {
  double best = hi;
  for (int k = 0; k < kAngles; ++k) {
    std::vector<PointD> rp;
    rp.reserve(pts.size());
    const double c = std::cos(sample(k)), s = std::sin(sample(k));
    for (const PointD& q : pts) rp.push_back({c * q.x + s * q.y, -s * q.x + c * q.y});
    // Only angles that can beat the best so far need the full bisection.
    if (oracle::max_cover_translation(poly, kind, best, rp) < pts.size()) continue;
    best = oracle::min_width_translation(poly, kind, rp, best);
  }
  return best;
}

// Largest distance of a point to the origin: rotating about the origin by dtheta moves no point
// further than this times dtheta, which turns the sampled minimum into a lower bound.
double radius(const std::vector<PointD>& pts) {
  double r = 0;
  for (const PointD& q : pts) r = std::max(r, std::hypot(q.x, q.y));
  return r;
}

RotationOptions with(RotationMethod m) {
  RotationOptions o;
  o.method = m;
  return o;
}

const RotationMethod kSearches[] = {RotationMethod::kCellSearch, RotationMethod::kAngleSearch};

TEST(RotationRoundVsOracle, MaxCoverIsConsistentWithSampling) {
  std::mt19937 rng(71);
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 8; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 3, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 7, 0.2, {u(rng), u(rng), 6.3 * u(rng)}, 0.3);
    const double delta = 0.05 + 0.15 * u(rng);
    const std::size_t sampled = oracle_cover(tp.vertices(), oracle::Kind::kRound, delta, pts);
    const MaxCoverResult translation = max_cover_translation(tp, OuterOffset::kRound, delta, pts);
    for (const RotationMethod m : kSearches) {
      const MaxCoverResult r = max_cover_rotation(tp, OuterOffset::kRound, delta, pts, with(m));
      const auto tag = ::testing::Message() << "trial " << trial << " method " << int(m);
      EXPECT_GE(r.upper_bound, sampled) << tag;
      EXPECT_GE(r.upper_bound, r.covered.size()) << tag;
      // The covered set really is covered (oracle distances, theta from the exact u).
      const oracle::Pose pose = pose_of(r.placement);
      std::size_t rechecked = 0;
      for (std::size_t i : r.covered) {
        rechecked += oracle::measure(tp.vertices(), oracle::Kind::kRound,
                                     oracle::to_template(pose, pts[i])) <= delta + 1e-9
                         ? 1
                         : 0;
      }
      EXPECT_EQ(rechecked, r.covered.size()) << tag;
      // Small inputs resolve: the certified optimum, at least the sampled and translation counts.
      EXPECT_EQ(r.covered.size(), r.upper_bound) << tag;
      EXPECT_GE(r.covered.size(), sampled) << tag;
      EXPECT_GE(r.covered.size(), translation.covered.size()) << tag;
    }
  }
}

TEST(RotationRoundVsOracle, MinimumWidthBracketsTheSampledOptimum) {
  std::mt19937 rng(73);
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 5; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 3, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 6, 0.15, {u(rng), u(rng), 6.3 * u(rng)});
    const MinWidthResult translation = min_width_translation(tp, OuterOffset::kRound, pts);
    const double sampled =
        oracle_width(tp.vertices(), oracle::Kind::kRound, pts, translation.delta_upper);
    // The true optimum lies in [sampled - radius * half step, sampled].
    const double sampled_lower = sampled - radius(pts) * std::numbers::pi / kAngles;
    std::vector<MinWidthResult> results;
    for (const RotationMethod m : kSearches) {
      const MinWidthResult r = min_width_rotation(tp, OuterOffset::kRound, pts, {}, with(m));
      const auto tag = ::testing::Message() << "trial " << trial << " method " << int(m);
      EXPECT_LE(r.delta_lower, r.delta_upper) << tag;
      EXPECT_LE(r.delta_lower, sampled + 1e-9) << tag;
      EXPECT_GE(r.delta_upper, sampled_lower - 1e-9) << tag;
      EXPECT_LE(r.delta_upper, sampled + 1e-9) << tag;       // sampling cannot beat the optimum
      EXPECT_LE(r.delta_upper - r.delta_lower, 1e-3) << tag; // and the search converged
      EXPECT_LE(r.delta_upper, translation.delta_upper + 1e-9) << tag;
      EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kRound, r.delta_upper,
                              pose_of(r.placement), pts, 1e-9),
                pts.size())
          << tag;
      results.push_back(r);
    }
    // Two certified intervals of the same optimum overlap.
    EXPECT_LE(std::max(results[0].delta_lower, results[1].delta_lower),
              std::min(results[0].delta_upper, results[1].delta_upper) + 1e-12);
  }
}

TEST(RotationRoundVsOracle, DecisionAgreesWellInsideAndOutside) {
  std::mt19937 rng(79);
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 4; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 2, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 6, 0.15, {u(rng), u(rng), 6.3 * u(rng)});
    const double hi = min_width_translation(tp, OuterOffset::kRound, pts).delta_upper;
    const double sampled = oracle_width(tp.vertices(), oracle::Kind::kRound, pts, hi);
    const double sampled_lower = sampled - radius(pts) * std::numbers::pi / kAngles;
    for (const RotationMethod m : kSearches) {
      const auto tag = ::testing::Message() << "trial " << trial << " method " << int(m);
      EXPECT_EQ(decide_rotation(tp, OuterOffset::kRound, 0.9 * sampled_lower, pts, with(m)).answer,
                Answer::kNo)
          << tag;
      const DecisionResult yes =
          decide_rotation(tp, OuterOffset::kRound, 1.1 * sampled, pts, with(m));
      ASSERT_EQ(yes.answer, Answer::kYes) << tag;
      EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kRound, 1.1 * sampled,
                              pose_of(yes.placement), pts, 1e-12),
                pts.size())
          << tag;
    }
  }
}

TEST(RotationRoundVsOracle, SimpleTemplates) {
  std::mt19937 rng(83);
  std::uniform_real_distribution<double> u(0, 1);
  // An L-shaped (non-convex) template.
  const TemplatePolygon tp =
      make_simple_template({{0, 0}, {2, 0}, {2, 0.8}, {0.8, 0.8}, {0.8, 2}, {0, 2}});
  for (unsigned trial = 0; trial < 2; ++trial) {
    const auto pts =
        oracle::points_near(rng, tp.vertices(), 5, 0.1, {u(rng), u(rng), 6.3 * u(rng)}, 0.2);
    const double delta = 0.06 + 0.05 * u(rng);
    const std::size_t sampled = oracle_cover(tp.vertices(), oracle::Kind::kSimple, delta, pts);
    const MaxCoverResult r = max_cover_rotation(tp, OuterOffset::kRound, delta, pts);
    EXPECT_GE(r.upper_bound, sampled) << "trial " << trial;
    EXPECT_EQ(
        oracle::count(tp.vertices(), oracle::Kind::kSimple, delta, pose_of(r.placement), pts, 1e-9),
        r.covered.size())
        << "trial " << trial;
    EXPECT_EQ(r.covered.size(), r.upper_bound) << "trial " << trial;
    const MinWidthResult w = min_width_rotation(tp, OuterOffset::kRound, pts);
    const double hi = min_width_translation(tp, OuterOffset::kRound, pts).delta_upper;
    EXPECT_LE(w.delta_upper, hi + 1e-9);
    EXPECT_LE(w.delta_lower, oracle_width(tp.vertices(), oracle::Kind::kSimple, pts, hi) + 1e-9);
    EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kSimple, w.delta_upper,
                            pose_of(w.placement), pts, 1e-9),
              pts.size());
  }
}

TEST(RotationRound, LinearizedCellsAgreeWithTheDiagram) {
  // Method 3 with the linearized offset against the exact diagram sweep (method 1).
  std::mt19937 rng(89);
  std::uniform_real_distribution<double> u(0, 1);
  for (unsigned trial = 0; trial < 6; ++trial) {
    const auto poly = oracle::random_convex(rng, 3 + trial % 3, 1.0);
    const TemplatePolygon tp = make_convex_template(poly);
    const auto pts = oracle::points_near(rng, poly, 12, 0.2, {u(rng), u(rng), 6.3 * u(rng)}, 0.2);
    const double delta = 0.05 + 0.15 * u(rng);
    const MaxCoverResult d = max_cover_rotation(tp, OuterOffset::kLinearized, delta, pts,
                                                with(RotationMethod::kDiagram));
    const MaxCoverResult c = max_cover_rotation(tp, OuterOffset::kLinearized, delta, pts,
                                                with(RotationMethod::kCellSearch));
    EXPECT_EQ(c.covered.size(), d.covered.size()) << "trial " << trial;
    EXPECT_GE(c.upper_bound, d.covered.size()) << "trial " << trial;
    EXPECT_GE(d.upper_bound, c.covered.size()) << "trial " << trial;
  }
}

TEST(RotationRound, BudgetExhaustionIsHonest) {
  std::mt19937 rng(97);
  std::uniform_real_distribution<double> u(0, 1);
  const auto poly = oracle::random_convex(rng, 5, 1.0);
  const TemplatePolygon tp = make_convex_template(poly);
  const auto pts = oracle::points_near(rng, poly, 6, 0.15, {0.3, 0.2, 1.0});
  RotationOptions tiny;
  tiny.max_cells = 20;
  tiny.max_evaluations = 4;
  const double hi = min_width_translation(tp, OuterOffset::kRound, pts).delta_upper;
  const double sampled = oracle_width(tp.vertices(), oracle::Kind::kRound, pts, hi);
  for (const RotationMethod m : kSearches) {
    tiny.method = m;
    const MinWidthResult w = min_width_rotation(tp, OuterOffset::kRound, pts, {}, tiny);
    EXPECT_LE(w.delta_lower, sampled + 1e-9);
    EXPECT_EQ(oracle::count(tp.vertices(), oracle::Kind::kRound, w.delta_upper,
                            pose_of(w.placement), pts, 1e-9),
              pts.size());
    // Just above the optimum a starved search may not find a witness, but never says NO.
    EXPECT_NE(decide_rotation(tp, OuterOffset::kRound, 1.02 * sampled, pts, tiny).answer,
              Answer::kNo);
  }
}

TEST(RotationRound, RejectsBadOptions) {
  const TemplatePolygon sq = make_convex_template({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  const std::vector<PointD> pts{{0, 1}, {1, 0}, {0, -1}};
  EXPECT_THROW(decide_rotation(sq, OuterOffset::kRound, 0.1, pts, with(RotationMethod::kDiagram)),
               InvalidInput);
  RotationOptions bad;
  bad.angle_resolution = 0.0;
  EXPECT_THROW(max_cover_rotation(sq, OuterOffset::kRound, 0.1, pts, bad), InvalidInput);
  const TemplatePolygon simple =
      make_simple_template({{0, 0}, {2, 0}, {2, 0.8}, {0.8, 0.8}, {0.8, 2}, {0, 2}});
  EXPECT_THROW(min_width_rotation(simple, OuterOffset::kLinearized, pts), InvalidInput);
}

TEST(RotationRound, DegenerateInputs) {
  const TemplatePolygon sq = make_convex_template({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  // One point, the same point many times, collinear points: answers stay certified.
  const std::vector<std::vector<PointD>> inputs{
      {{5, 5}}, std::vector<PointD>(50, PointD{2, 3}), {{0, 0}, {0.6, 0}, {1.2, 0}, {1.8, 0}}};
  for (const auto& pts : inputs) {
    const DecisionResult d = decide_rotation(sq, OuterOffset::kRound, 0.1, pts);
    ASSERT_EQ(d.answer, Answer::kYes) << pts.size();
    EXPECT_EQ(oracle::count(sq.vertices(), oracle::Kind::kRound, 0.1, pose_of(d.placement), pts),
              pts.size());
    const MaxCoverResult c = max_cover_rotation(sq, OuterOffset::kRound, 0.1, pts);
    EXPECT_EQ(c.covered.size(), pts.size());
    EXPECT_EQ(c.upper_bound, pts.size());
    const MinWidthResult w = min_width_rotation(sq, OuterOffset::kRound, pts);
    EXPECT_LE(w.delta_lower, w.delta_upper);
    EXPECT_EQ(oracle::count(sq.vertices(), oracle::Kind::kRound, w.delta_upper,
                            pose_of(w.placement), pts, 1e-9),
              pts.size());
  }
  // Four collinear points spanning 3 (more than a side, about the diagonal): the inner two are
  // deep inside whenever the outer two are near the boundary, so the width is large.
  const std::vector<PointD> line{{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  const MinWidthResult w = min_width_rotation(sq, OuterOffset::kRound, line);
  EXPECT_GT(w.delta_lower, 0.2);
  EXPECT_EQ(decide_rotation(sq, OuterOffset::kRound, 0.1, line).answer, Answer::kNo);
}

} // namespace
} // namespace penshape::annulus
