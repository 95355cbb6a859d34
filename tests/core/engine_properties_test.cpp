// Properties of the decider on random, generated and real polygons: interior ⊆ exterior
// approximations, answers monotone in eps, engines never contradict, every polygon runs. The
// real polygons come from the shared corpus (skipped without it); the generated ones
// (tests/support/gen: coastline, staircase, comb, spikes, holes, thin features) always run.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <numbers>
#include <random>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/disk_approximation.hpp"
#include "penshape/core/offset.hpp"
#include "penshape/core/polygon_io.hpp"
#include "polygon_gen.hpp"
#include "support/hausdorff_check.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

// A random star-shaped polygon around the origin: simple by construction (increasing angles).
PolygonSet random_star(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> radius(4.0, 10.0);
  std::uniform_real_distribution<double> jitter(0.0, 0.8);
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + jitter(rng)) / n;
    const double r = radius(rng);
    // Round to 1/64 so coordinates are small exact dyadics.
    ring.push_back({exact(std::round(r * std::cos(a) * 64) / 64),
                    exact(std::round(r * std::sin(a) * 64) / 64)});
  }
  return {{{ring, {}}}};
}

Rational width(const PolygonSet& q) {
  Rational lo = q.polygons[0].outer[0].x, hi = lo;
  for (const auto& p : q.polygons) {
    for (const auto& v : p.outer) {
      lo = std::min(lo, v.x);
      hi = std::max(hi, v.x);
    }
  }
  return hi - lo;
}

TEST(EngineProperties, InteriorApproximationInsideExterior) {
  std::mt19937 rng(7);
  const Rational r(3, 2), e(1, 2), d(1, 16);
  for (int t = 0; t < 6; ++t) {
    const PolygonSet q = random_star(rng, 12 + 3 * t);
    // Π̂ of Algorithm 2 (interior) and of Algorithm 3 (exterior), with the public exact ops.
    const PolygonSet pi_in = inset_by(offset_by(q, disk_approximation(e - d, e, 4096)),
                                      disk_approximation(r, r + d, 4096));
    const PolygonSet pi_out = inset_by(offset_by(q, disk_approximation(e, e + d, 4096)),
                                       disk_approximation(r - d, r, 4096));
    ASSERT_FALSE(pi_out.empty());
    if (!pi_in.empty()) {
      EXPECT_TRUE(region_contains(pi_out, pi_in)) << "trial " << t;
    }
    EXPECT_LE(area(pi_in), area(pi_out));
    // And the offset steps nest the other way round around Q.
    EXPECT_TRUE(region_contains(offset_by(q, disk_approximation(e - d, e, 4096)), q));
  }
}

TEST(EngineProperties, AnswersAreMonotoneInTolerance) {
  std::mt19937 rng(11);
  const Rational r(2);
  const Rational d(1, 64);
  const Rational eps[] = {Rational(1, 8), Rational(1, 4), Rational(1, 2), Rational(1)};
  for (int t = 0; t < 4; ++t) {
    const PolygonSet q = random_star(rng, 10 + 4 * t);
    Answer previous = Answer::kNo;
    for (const auto& e : eps) {
      const auto res = deconstruct(q, {r, e, d, EngineKind::kReference});
      // A YES at a smaller eps forbids NO at a larger one; NO after YES would contradict.
      if (previous == Answer::kYes) {
        EXPECT_NE(res.answer, Answer::kNo) << "trial " << t;
      }
      if (res.answer == Answer::kYes) previous = Answer::kYes;
    }
  }
}

TEST(EngineProperties, EnginesNeverContradict) {
  std::mt19937 rng(3);
  for (int t = 0; t < 6; ++t) {
    const PolygonSet q = random_star(rng, 8 + 5 * t);
    const DeconstructParams base{Rational(3, 2), Rational(1, 2), Rational(1, 16),
                                 EngineKind::kReference};
    auto fast = base;
    fast.engine = EngineKind::kFast;
    const auto a = deconstruct(q, base);
    const auto b = deconstruct(q, fast);
    const bool contradict = (a.answer == Answer::kYes && b.answer == Answer::kNo) ||
                            (a.answer == Answer::kNo && b.answer == Answer::kYes);
    EXPECT_FALSE(contradict) << "trial " << t << ": " << to_string(a.answer) << " vs "
                             << to_string(b.answer);
  }
}

void expect_engines_agree(const PolygonSet& q, const std::string& name) {
  for (int divisor : {10, 30}) {
    SCOPED_TRACE(name + " r = w/" + std::to_string(divisor));
    const Rational r = width(q) / divisor;
    const DeconstructParams base{r, r / 2, r / 16, EngineKind::kReference};
    auto fast = base;
    fast.engine = EngineKind::kFast;
    const Answer a = deconstruct(q, base).answer;
    const Answer b = deconstruct(q, fast).answer;
    EXPECT_FALSE((a == Answer::kYes && b == Answer::kNo) || (a == Answer::kNo && b == Answer::kYes))
        << to_string(a) << " vs " << to_string(b);
  }
}

TEST(EngineProperties, EnginesNeverContradictOnRealPolygons) {
  PENSHAPE_SHARED_OR_SKIP(dir, "polygons");
  for (const char* name :
       {"authors_demo_1_01_work1.txt", "authors_demo_1_01_fail2.txt", "authors_S.txt",
        "cgal_wheel1.txt", "cgal_comb_robot.txt", "israel_ne50m.txt", "cgal_knife.txt"}) {
    expect_engines_agree(read_polygon_text(test::read_file(dir / name)), name);
  }
}

TEST(EngineProperties, EnginesNeverContradictOnGeneratedPolygons) {
  for (const auto& g : gen::polygon_suite(17)) {
    if (g.name != "country_1881") expect_engines_agree(read_polygon_text(g.text), g.name);
  }
}

// Every polygon at r = w/10, w/30, w/50, eps = r/2, delta = eps/8 with the reference engine: no
// crash, no hang (a 20 s deadline per case through the cancel hook; a cancelled case counts as
// finished cleanly), and every YES checked independently on the polygons of up to 300 vertices
// (the check samples a grid of spacing w/150, so it is loose but independent).
void expect_runs(const PolygonSet& q, const std::string& name) {
  const Rational w = width(q);
  for (int divisor : {10, 30, 50}) {
    SCOPED_TRACE(name + " r = w/" + std::to_string(divisor));
    const Rational r = w / divisor;
    const Rational e = r / 2;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    DeconstructResult res;
    try {
      res = deconstruct(q, {r, e, e / 8, EngineKind::kReference},
                        [&] { return std::chrono::steady_clock::now() > deadline; });
    } catch (const Cancelled&) {
      continue;
    }
    if (res.answer == Answer::kYes && q.vertex_count() <= 300) {
      const auto h = test::hausdorff_to_offset(test::region_skeleton(res.solution), r.get_d(),
                                               test::to_region_d(q), w.get_d() / 150);
      EXPECT_LE(h.value, e.get_d() + h.error + 1e-9);
    }
  }
}

TEST(EngineProperties, EverySharedPolygonRuns) {
  PENSHAPE_SHARED_OR_SKIP(dir, "polygons");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".txt") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 20U);
  for (const auto& path : files) {
    expect_runs(read_polygon_text(test::read_file(path.string())), path.filename().string());
  }
}

TEST(EngineProperties, EveryGeneratedPolygonRuns) {
  for (const auto& g : gen::polygon_suite(5)) expect_runs(read_polygon_text(g.text), g.name);
}

} // namespace
} // namespace penshape
