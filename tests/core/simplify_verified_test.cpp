// Simplified YES solutions are accepted by the independent verifier (penshape/core/verify.hpp):
// on generated non-convex polygons (every clone; one over 2^15 vertices) and on the paper's
// Kazakhstan polygon at r = w/30, ε = r/2, δ = ε/8, where the simplification must also reach at
// most 91 vertices (issue 26; skipped without the shared corpus).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "penshape/core/simplify.hpp"
#include "penshape/core/validated_region.hpp"
#include "penshape/core/verify.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

// A wavy ring of n vertices on a 1/64 grid: radius 10 ± 2 (times `scale`) with 7 lobes, so it
// is not convex.
PolygonSet wavy_ring(int n, double scale = 1) {
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    const double rad = scale * (10 + 2 * std::sin(7 * a));
    ring.push_back({exact(std::round(rad * std::cos(a) * 64) / 64),
                    exact(std::round(rad * std::sin(a) * 64) / 64)});
  }
  return {{{std::move(ring), {}}}};
}

// Decides with the fast engine, simplifies, and has the verifier check the simplified claim.
SimplifyResult simplify_and_verify(const PolygonSet& q, const Rational& r) {
  const DeconstructParams params{r, r / 2, r / 16, EngineKind::kFast};
  const DeconstructResult raw = deconstruct(q, params);
  EXPECT_EQ(raw.answer, Answer::kYes);
  if (raw.answer != Answer::kYes) return {};
  SimplifyResult s = simplify_solution(q, raw);
  const DeconstructionClaim claim{
      Answer::kYes,      r,           s.result.params.tolerance, s.result.params.precision,
      s.result.solution, std::nullopt};
  const VerifyReport rep = verify_deconstruction(q, claim);
  EXPECT_EQ(rep.status, VerifyStatus::kVerified) << rep.message;
  return s;
}

// The same polygons, ring by ring and vertex by vertex (exact).
bool same(const PolygonSet& a, const PolygonSet& b) {
  if (a.polygons.size() != b.polygons.size()) return false;
  for (std::size_t i = 0; i < a.polygons.size(); ++i) {
    if (a.polygons[i].outer != b.polygons[i].outer || a.polygons[i].holes != b.polygons[i].holes)
      return false;
  }
  return true;
}

TEST(SimplifyVerified, GeneratedPolygon) {
  const PolygonSet q = wavy_ring(400);
  const SimplifyResult s = simplify_and_verify(q, Rational(1, 2));
  EXPECT_TRUE(s.simplified);
  EXPECT_LT(s.solution_vertices, s.raw_vertices);
}

// Over 2^15 vertices the simplifier checks against the decision's coarser Q_s (issue 26): still
// certified, and still simplifying.
TEST(SimplifyVerified, LargeGeneratedPolygon) {
  const PolygonSet q = wavy_ring(40'000, 100);
  const SimplifyResult s = simplify_and_verify(q, Rational(50));
  EXPECT_TRUE(s.simplified);
  EXPECT_LT(s.solution_vertices, s.raw_vertices);
  // deconstruct_simplified, whose simplifier reuses the decision's grid, Q_s (the decision's own
  // on this large input) and walk memo: the same solution.
  const DeconstructParams params{Rational(50), Rational(25), Rational(25, 8), EngineKind::kFast};
  const SimplifyResult both = deconstruct_simplified(ValidatedRegion::validate(q), params);
  EXPECT_TRUE(both.simplified);
  EXPECT_TRUE(same(both.result.solution, s.result.solution));
  EXPECT_EQ(both.raw_vertices, s.raw_vertices);
}

// Small input (the simplifier's own finer Q_s, the decision's grid), a NO and a convex input
// (no fast work kept): deconstruct_simplified answers as deconstruct + simplify_solution.
TEST(SimplifyVerified, DeconstructSimplifiedMatchesTheTwoCalls) {
  const PolygonSet wavy = wavy_ring(400);
  const PolygonSet square{{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}}}};
  for (const auto& [q, r] : {std::pair{wavy, Rational(1, 2)}, std::pair{wavy, Rational(30)},
                             std::pair{square, Rational(2)}}) {
    const DeconstructParams params{r, r / 2, r / 16, EngineKind::kFast};
    const DeconstructResult raw = deconstruct(q, params);
    const SimplifyResult both = deconstruct_simplified(ValidatedRegion::validate(q), params);
    EXPECT_EQ(both.result.answer, raw.answer) << to_double(r);
    if (raw.answer != Answer::kYes) continue;
    const SimplifyResult s = simplify_solution(q, raw);
    EXPECT_TRUE(same(both.result.solution, s.result.solution)) << to_double(r);
    EXPECT_EQ(both.solution_vertices, s.solution_vertices);
  }
}

TEST(SimplifyVerified, KazakhstanAtWidthOver30) {
  PENSHAPE_SHARED_OR_SKIP(path, "polygons/kazakhstan_paper1881.txt");
  const PolygonSet q = read_polygon_text(test::read_file(path));
  const Ring& ring = q.polygons.at(0).outer; // one ring; w is its width in x
  const auto [lo, hi] = std::minmax_element(
      ring.begin(), ring.end(), [](const ExactPoint& a, const ExactPoint& b) { return a.x < b.x; });
  const SimplifyResult s = simplify_and_verify(q, (hi->x - lo->x) / 30);
  EXPECT_TRUE(s.simplified);
  EXPECT_LE(s.solution_vertices, 91U) << "raw " << s.raw_vertices;
}

} // namespace
} // namespace penshape
