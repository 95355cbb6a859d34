// Issue-5 properties with the real engines, on real polygons and strokes (the shared corpus,
// skipped without it) and on generated ones (tests/support/gen): ε̂(r) monotone and 1-Lipschitz,
// the ε̂ interval agreeing with the decider at its ends, CONVEXDECIDE agreeing with the general
// decider, and simplified solutions keeping the certificate — each checked independently.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

#include "penshape/core/convex_deconstruct.hpp"
#include "penshape/core/ink.hpp"
#include "penshape/core/polygon_io.hpp"
#include "penshape/core/search.hpp"
#include "penshape/core/simplify.hpp"
#include "polygon_gen.hpp"
#include "stroke_gen.hpp"
#include "support/dollar1.hpp"
#include "support/hausdorff_check.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

PolygonSet shared_polygon(const std::filesystem::path& dir, const std::string& name) {
  return read_polygon_text(test::read_file(dir / (name + ".txt")));
}

// A generated coastline of the size of the authors' S (about 100 units across).
PolygonSet generated_coast() { return read_polygon_text(gen::country(12, 160, 50.0).text); }

double bbox_width(const PolygonSet& q) {
  double lo = INFINITY;
  double hi = -INFINITY;
  for (const auto& p : q.polygons) {
    for (const auto& v : p.outer) {
      lo = std::min(lo, to_double(v.x));
      hi = std::max(hi, to_double(v.x));
    }
  }
  return hi - lo;
}

// H(offset(P, r), Q) <= ε up to the independent check's own sampling error.
void expect_certified(const PolygonSet& q, const DeconstructResult& res) {
  ASSERT_EQ(res.answer, Answer::kYes);
  const double r = to_double(res.params.radius);
  const double spacing = std::max(r / 40, bbox_width(q) / 400);
  const auto h = test::hausdorff_to_offset(test::region_skeleton(res.solution), r,
                                           test::to_region_d(q), spacing);
  EXPECT_LE(h.value, to_double(res.params.tolerance) + h.error + 1e-9)
      << "r = " << r << " eps = " << to_double(res.params.tolerance);
}

Rational rational_of(double v) { return exact(v); }

void expect_eps_hat_monotone_and_lipschitz(const PolygonSet& q, const std::string& name) {
  {
    const double w = bbox_width(q);
    const Decider decide = make_decider(q, EngineKind::kFast);
    std::vector<ToleranceSearchResult> at;
    std::vector<double> radii = {w / 40, w / 30, w / 20, w / 15};
    for (const double r : radii) {
      at.push_back(search_tolerance(decide, rational_of(r), rational_of(r / 50)));
      expect_certified(q, at.back().solution);
    }
    for (std::size_t i = 0; i < at.size(); ++i) {
      for (std::size_t j = i + 1; j < at.size(); ++j) {
        // Monotone: ε̂(r_i) <= ε̂(r_j), so the intervals cannot be ordered the other way.
        EXPECT_LE(at[i].eps_low, at[j].eps_high) << name << " " << i << " " << j;
        // 1-Lipschitz: ε̂(r_j) - ε̂(r_i) <= r_j - r_i.
        EXPECT_LE(to_double(at[j].eps_low - at[i].eps_high), radii[j] - radii[i] + 1e-12) << name;
      }
    }
  }
}

TEST(SearchEngine, EpsHatIsMonotoneAndLipschitzOnRealPolygons) {
  PENSHAPE_SHARED_OR_SKIP(dir, "polygons");
  for (const char* name : {"authors_S", "cgal_knife_blade", "authors_concave"})
    expect_eps_hat_monotone_and_lipschitz(shared_polygon(dir, name), name);
}

TEST(SearchEngine, EpsHatIsMonotoneAndLipschitzOnGeneratedPolygons) {
  expect_eps_hat_monotone_and_lipschitz(generated_coast(), "coast");
  expect_eps_hat_monotone_and_lipschitz(read_polygon_text(gen::comb(6, 10, 6, 40).text), "comb");
}

void expect_interval_ends_agree(const PolygonSet& q) {
  const double r = bbox_width(q) / 25;
  const Rational radius = rational_of(r);
  const Decider decide = make_decider(q, EngineKind::kFast);
  const auto res = search_tolerance(decide, radius, radius / 100);
  const Rational width = res.eps_high - res.eps_low;
  // Just above the interval the answer is YES; well below it NO, at a fine enough δ.
  EXPECT_EQ(decide(radius, res.eps_high + width, width / 8).answer, Answer::kYes);
  if (res.eps_low > 2 * width) {
    EXPECT_EQ(decide(radius, res.eps_low - width, width / 8).answer, Answer::kNo);
  }
}

TEST(SearchEngine, IntervalEndsAgreeWithTheDecider) {
  PENSHAPE_SHARED_OR_SKIP(dir, "polygons");
  expect_interval_ends_agree(shared_polygon(dir, "authors_S"));
}

TEST(SearchEngine, IntervalEndsAgreeWithTheDeciderOnAGeneratedPolygon) {
  expect_interval_ends_agree(generated_coast());
}

void expect_radius_search_brackets_r_star(const PolygonSet& q) {
  const double w = bbox_width(q);
  const Rational eps = rational_of(w / 60);
  const Decider decide = make_decider(q, EngineKind::kFast);
  RadiusSearchOptions opt;
  opt.precision = eps / 4;
  opt.max_decider_calls = 80;
  const auto res = search_radius(decide, eps, enclosing_radius_bound(q) + eps, opt);
  ASSERT_EQ(res.solution_at_low.answer, Answer::kYes);
  expect_certified(q, res.solution_at_low);
  // r_low has a solution; r_high (when it is a tested radius) has none: ε̂(r_high) >= ε.
  const auto above = search_tolerance(decide, res.r_high, res.r_high / 200);
  EXPECT_GE(above.eps_high, eps - res.r_high / 200);
}

TEST(SearchEngine, RadiusSearchBracketsRStar) {
  PENSHAPE_SHARED_OR_SKIP(dir, "polygons");
  expect_radius_search_brackets_r_star(shared_polygon(dir, "authors_S"));
}

TEST(SearchEngine, RadiusSearchBracketsRStarOnAGeneratedPolygon) {
  expect_radius_search_brackets_r_star(generated_coast());
}

TEST(SearchEngine, ConvexDecideAgreesWithTheGeneralDecider) {
  std::mt19937 rng(21);
  int compared = 0;
  for (int trial = 0; trial < 12; ++trial) {
    PolygonSet q;
    q.polygons.emplace_back();
    const int n = 5 + trial;
    for (int k = 0; k < n; ++k) {
      const double a =
          2 * std::numbers::pi * (k + 0.3 * std::uniform_real_distribution<double>(0, 1)(rng)) / n;
      q.polygons[0].outer.push_back(
          exact(PointD{std::round(100 * std::cos(a)), std::round(70 * std::sin(a))}));
    }
    if (!is_convex_region(q)) continue;
    for (const double eps : {1.0, 3.0, 6.0}) {
      const DeconstructParams p{exact(10.0), exact(eps), exact(eps / 8), EngineKind::kReference};
      const Answer general = deconstruct(q, p).answer;
      const Answer convex = convex_decide(q, p).answer;
      if (general != Answer::kUndecided && convex != Answer::kUndecided) {
        EXPECT_EQ(general, convex) << trial << " eps " << eps;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 10);
}

// Simplifies the solution at r = w/30; true when it was simplified.
bool expect_simplified_certified(const PolygonSet& q, const std::string& name) {
  {
    const double r = bbox_width(q) / 30;
    const DeconstructParams p{exact(r), exact(r / 2), exact(r / 16), EngineKind::kFast};
    const DeconstructResult raw = deconstruct(q, p);
    if (raw.answer != Answer::kYes) return false;
    const SimplifyResult s = simplify_solution(q, raw);
    EXPECT_LE(s.solution_vertices, s.raw_vertices) << name;
    expect_certified(q, s.result);
    std::printf("%-28s raw %4zu -> simplified %4zu (tau %.4g)\n", name.c_str(), s.raw_vertices,
                s.solution_vertices, to_double(s.tau));
    return s.simplified;
  }
}

TEST(SearchEngine, SimplificationKeepsTheCertificateOnSharedPolygons) {
  PENSHAPE_SHARED_OR_SKIP(dir, "polygons");
  std::size_t simplified = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    const std::string name = entry.path().stem().string();
    simplified += expect_simplified_certified(shared_polygon(dir, name), name) ? 1 : 0;
  }
  EXPECT_GE(simplified, 5U);
}

TEST(SearchEngine, SimplificationKeepsTheCertificateOnGeneratedPolygons) {
  std::size_t simplified = 0;
  for (const auto& g : gen::polygon_suite(31))
    simplified += expect_simplified_certified(read_polygon_text(g.text), g.name) ? 1 : 0;
  EXPECT_GE(simplified, 2U);
}

} // namespace
} // namespace penshape

namespace penshape {
namespace {

TEST(SearchEngine, NearlyStraightStrokeBecomesASegment) {
  // A 60 mm stroke with a wobble well below ε, inked with a 1 mm pen.
  std::vector<InkSample> samples;
  for (int i = 0; i <= 120; ++i) {
    const double t = i / 120.0;
    samples.push_back({60 * t, 20 * t + 0.08 * std::sin(23 * t), 1.0});
  }
  InkOptions opt;
  opt.radius_mm = 1.0;
  const InkPolygon ink = ink_polygon(samples, opt);
  const DeconstructParams p{exact(1.0), exact(0.5), exact(0.5 / 8), EngineKind::kFast};
  const DeconstructResult raw = deconstruct(ink.region, p);
  ASSERT_EQ(raw.answer, Answer::kYes);
  const SimplifyResult s = simplify_solution(ink.region, raw);
  EXPECT_EQ(s.solution_vertices, 2U) << "raw " << s.raw_vertices;
  expect_certified(ink.region, s.result);
}

void expect_stroke_simplified_certified(const std::vector<PointD>& points,
                                        const std::string& file) {
  {
    std::vector<InkSample> samples;
    samples.reserve(points.size());
    for (const auto& pt : points) samples.push_back({pt.x, pt.y, 3.0});
    InkOptions opt;
    opt.radius_mm = 3.0;
    const InkPolygon ink = ink_polygon(samples, opt);
    const DeconstructParams p{exact(3.0), exact(1.5), exact(1.5 / 8), EngineKind::kFast};
    const DeconstructResult raw = deconstruct(ink.region, p);
    if (raw.answer != Answer::kYes) return;
    const SimplifyResult s = simplify_solution(ink.region, raw);
    EXPECT_LE(s.solution_vertices, s.raw_vertices) << file;
    expect_certified(ink.region, s.result);
    std::printf("%-28s raw %4zu -> simplified %4zu\n", file.c_str(), s.raw_vertices,
                s.solution_vertices);
  }
}

TEST(SearchEngine, SimplificationKeepsTheCertificateOnRealStrokes) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/dollar1");
  for (const char* file : {"s02/medium/circle01.xml", "s03/fast/triangle05.xml",
                           "s04/slow/pigtail03.xml", "s05/medium/rectangle02.xml"}) {
    expect_stroke_simplified_certified(test::read_dollar1((dir / file).string()), file);
  }
}

TEST(SearchEngine, SimplificationKeepsTheCertificateOnGeneratedStrokes) {
  gen::StrokeGenerator strokes(41);
  for (const char* kind : {"circle", "triangle", "spiral", "rectangle"}) {
    std::vector<PointD> points;
    const gen::Drawing drawing = strokes.draw(kind);
    for (const auto& p : drawing.strokes.front().points) points.push_back({p.x, p.y});
    expect_stroke_simplified_certified(points, kind);
  }
}

} // namespace
} // namespace penshape
