// The independent verifier (penshape/core/verify.hpp) against the engines' answers: it accepts
// every answer they give on synthetic polygons (always) and on the shared polygons (when
// present), and it rejects corrupted answers whose fault an independent double-precision
// Hausdorff estimate (tests/core/support) confirms: a vertex moved by 2ε, ε shrunk below the
// true distance, a NO witness swapped for a point a solution serves.
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <random>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "penshape/core/simplify.hpp"
#include "penshape/core/verify.hpp"
#include "support/hausdorff_check.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

Ring ring_of(std::initializer_list<std::pair<double, double>> pts) {
  Ring r;
  for (const auto& [x, y] : pts) r.push_back({exact(x), exact(y)});
  return r;
}

PolygonSet one(Ring outer, std::vector<Ring> holes = {}) {
  return {{{std::move(outer), std::move(holes)}}};
}

PolygonSet random_star(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> radius(4.0, 10.0);
  std::uniform_real_distribution<double> jitter(0.0, 0.8);
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + jitter(rng)) / n;
    const double r = radius(rng);
    ring.push_back({exact(std::round(r * std::cos(a) * 64) / 64),
                    exact(std::round(r * std::sin(a) * 64) / 64)});
  }
  return one(ring);
}

// A 20 × 20 square with a spike 0.2 wide and 10 long: with r = 1 and ε = 1/4 nothing can reach
// the spike's tip (offset(P, 1) is at least 2 wide), so the answer is NO.
PolygonSet square_with_spike() {
  return one(
      ring_of({{0, 0}, {20, 0}, {20, 9.9}, {30, 9.9}, {30, 10.1}, {20, 10.1}, {20, 20}, {0, 20}}));
}

std::vector<PolygonSet> synthetic_polygons() {
  std::vector<PolygonSet> out;
  out.push_back(one(ring_of({{0, 0}, {10, 0}, {10, 10}, {0, 10}})));
  out.push_back(one(ring_of({{0, 0}, {12, 0}, {12, 4}, {4, 4}, {4, 12}, {0, 12}})));
  out.push_back(one(ring_of({{0, 0}, {16, 0}, {16, 16}, {0, 16}}),
                    {ring_of({{5, 5}, {5, 11}, {11, 11}, {11, 5}})}));
  out.push_back(one(ring_of({{0, 0},
                             {3, 0},
                             {3, 8},
                             {5, 8},
                             {5, 0},
                             {8, 0},
                             {8, 8},
                             {10, 8},
                             {10, 0},
                             {13, 0},
                             {13, 12},
                             {0, 12}})));
  out.push_back(square_with_spike());
  std::mt19937 rng(11);
  for (int k = 0; k < 3; ++k) out.push_back(random_star(rng, 14 + 5 * k));
  return out;
}

DeconstructionClaim claim_of(const DeconstructResult& res) {
  return {res.answer,           res.params.radius, res.params.tolerance,
          res.params.precision, res.solution,      res.no_witness};
}

// Every answer of both engines (and the simplified YES) at a few radii: verified.
TEST(VerifyDeconstruction, AcceptsEngineAnswersOnSyntheticPolygons) {
  int yes = 0, no = 0;
  for (const PolygonSet& q : synthetic_polygons()) {
    for (const auto& [r, e] :
         {std::pair{Rational(1), Rational(1, 4)}, std::pair{Rational(2), Rational(1, 2)},
          std::pair{Rational(3), Rational(3, 2)}}) {
      for (const EngineKind engine : {EngineKind::kFast, EngineKind::kReference}) {
        const DeconstructParams params{r, e, e / 8, engine};
        const DeconstructResult res = deconstruct(q, params);
        const VerifyReport rep = verify_deconstruction(q, claim_of(res));
        EXPECT_EQ(rep.status, VerifyStatus::kVerified)
            << to_string(res.answer) << " r=" << r << " e=" << e << " " << to_string(engine) << ": "
            << rep.message << "\n"
            << to_wkt(q);
        yes += res.answer == Answer::kYes;
        no += res.answer == Answer::kNo;
        if (res.answer == Answer::kYes) {
          const SimplifyResult s = simplify_solution(q, res);
          const VerifyReport rs = verify_deconstruction(q, claim_of(s.result));
          EXPECT_EQ(rs.status, VerifyStatus::kVerified) << "simplified: " << rs.message;
        }
      }
    }
  }
  EXPECT_GT(yes, 10);
  EXPECT_GT(no, 1);
}

test::HausdorffEstimate estimate(const PolygonSet& p, const Rational& r, const PolygonSet& q) {
  return test::hausdorff_to_offset(test::region_skeleton(p), r.get_d(), test::to_region_d(q), 0.05);
}

// A vertex of P moved by 2ε, where the independent estimate shows H > ε: rejected.
TEST(VerifyDeconstruction, RejectsVertexMovedByTwoEps) {
  const PolygonSet q = one(ring_of({{0, 0}, {12, 0}, {12, 4}, {4, 4}, {4, 12}, {0, 12}}));
  const DeconstructResult res = deconstruct(q, {Rational(2), Rational(1, 2), Rational(1, 16)});
  ASSERT_EQ(res.answer, Answer::kYes);
  int tried = 0;
  for (std::size_t i = 0; i < res.solution.polygons[0].outer.size(); ++i) {
    for (const auto& [dx, dy] : {std::pair{1, 0}, {0, 1}, {-1, 0}, {0, -1}}) {
      DeconstructionClaim c = claim_of(res);
      ExactPoint& v = c.solution.polygons[0].outer[i];
      v.x += 2 * c.tolerance * dx;
      v.y += 2 * c.tolerance * dy;
      const auto h = estimate(c.solution, c.radius, q);
      if (h.value - h.error <= c.tolerance.get_d()) continue; // maybe still a solution
      ++tried;
      EXPECT_NE(verify_deconstruction(q, c).status, VerifyStatus::kVerified) << "vertex " << i;
    }
  }
  EXPECT_GT(tried, 3);
}

// ε (and δ with it) shrunk below the true distance, by the independent estimate: rejected with a
// counterexample point.
TEST(VerifyDeconstruction, RejectsToleranceBelowTrueDistance) {
  for (const PolygonSet& q : synthetic_polygons()) {
    const DeconstructResult res = deconstruct(q, {Rational(2), Rational(1, 2), Rational(1, 16)});
    if (res.answer != Answer::kYes) continue;
    const auto h = estimate(res.solution, res.params.radius, q);
    const double lower = h.value - h.error;
    ASSERT_GT(lower, 0.05);
    DeconstructionClaim c = claim_of(res);
    c.tolerance = exact(0.8 * lower);
    c.precision = c.tolerance / 8;
    const VerifyReport rep = verify_deconstruction(q, c);
    EXPECT_EQ(rep.status, VerifyStatus::kRefuted) << rep.message;
  }
}

// The spike's NO witness verifies; the square's centre (its r-disk lies in Q, so it is in Π and
// P = Π serves it) does not.
TEST(VerifyDeconstruction, RejectsNoWitnessSwappedWithServedPoint) {
  const PolygonSet q = square_with_spike();
  for (const EngineKind engine : {EngineKind::kFast, EngineKind::kReference}) {
    const DeconstructResult res =
        deconstruct(q, {Rational(1), Rational(1, 4), Rational(1, 32), engine});
    ASSERT_EQ(res.answer, Answer::kNo) << to_string(engine);
    ASSERT_TRUE(res.no_witness.has_value());
    DeconstructionClaim c = claim_of(res);
    EXPECT_EQ(verify_deconstruction(q, c).status, VerifyStatus::kVerified);
    c.no_witness = ExactPoint{Rational(10), Rational(10)};
    EXPECT_NE(verify_deconstruction(q, c).status, VerifyStatus::kVerified);
    c.no_witness = ExactPoint{Rational(40), Rational(10)}; // not in Q at all
    EXPECT_EQ(verify_deconstruction(q, c).status, VerifyStatus::kRefuted);
    c.no_witness.reset();
    EXPECT_NE(verify_deconstruction(q, c).status, VerifyStatus::kVerified);
  }
}

TEST(VerifyDeconstruction, RejectsInvalidSolutionRegion) {
  const PolygonSet q = one(ring_of({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  DeconstructionClaim c{Answer::kYes, Rational(2), Rational(1), Rational(1, 8), {}, {}};
  c.solution = one(ring_of({{2, 2}, {8, 8}, {8, 2}, {2, 8}})); // a bow tie
  const VerifyReport rep = verify_deconstruction(q, c);
  EXPECT_EQ(rep.status, VerifyStatus::kRefuted);
  EXPECT_NE(rep.message.find("not a valid region"), std::string::npos) << rep.message;
}

TEST(VerifyDeconstruction, BadParametersThrow) {
  const PolygonSet q = one(ring_of({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  DeconstructionClaim c{Answer::kUndecided, Rational(2), Rational(1), Rational(1), {}, {}};
  EXPECT_THROW((void)verify_deconstruction(q, c), InvalidInput);
  c.precision = Rational(1, 8);
  c.radius = 0;
  EXPECT_THROW((void)verify_deconstruction(q, c), InvalidInput);
}

// Every shared polygon at r = w/30, ε = r/2, δ = ε/8: the fast engine's raw and simplified answers
// verify, and the reference engine's on polygons of up to 500 vertices.
TEST(VerifyDeconstruction, AcceptsAnswersOnSharedPolygons) {
  PENSHAPE_SHARED_OR_SKIP(dir, "polygons");
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    const PolygonSet q = read_polygon_text(test::read_file(entry.path()));
    Rational lo = q.polygons[0].outer[0].x, hi = lo;
    for (const auto& v : q.polygons[0].outer) {
      lo = std::min(lo, v.x);
      hi = std::max(hi, v.x);
    }
    const Rational r = (hi - lo) / 30;
    const DeconstructParams params{r, r / 2, r / 16};
    DeconstructResult res;
    try {
      res = deconstruct(q, params);
    } catch (const InvalidInput&) {
      continue; // not a valid region for the engines either
    }
    const VerifyReport rep = verify_deconstruction(q, claim_of(res));
    EXPECT_EQ(rep.status, VerifyStatus::kVerified)
        << entry.path().filename() << " " << to_string(res.answer) << ": " << rep.message;
    if (res.answer == Answer::kYes) {
      const SimplifyResult s = simplify_solution(q, res);
      const VerifyReport rs = verify_deconstruction(q, claim_of(s.result));
      EXPECT_EQ(rs.status, VerifyStatus::kVerified)
          << entry.path().filename() << " simplified: " << rs.message;
    }
    if (q.vertex_count() <= 500) { // the reference engine too, where it is quick
      DeconstructParams ref = params;
      ref.engine = EngineKind::kReference;
      const DeconstructResult rr = deconstruct(q, ref);
      const VerifyReport rv = verify_deconstruction(q, claim_of(rr));
      EXPECT_EQ(rv.status, VerifyStatus::kVerified)
          << entry.path().filename() << " reference " << to_string(rr.answer) << ": " << rv.message;
    }
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

} // namespace
} // namespace penshape
