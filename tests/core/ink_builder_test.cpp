// InkBuilder: Q built a chunk at a time while the stroke is drawn equals the one-shot
// ink_polygon() bit for bit (random and real strokes, pen-up mid-chunk or on a chunk's end, a
// prefix that changed, a plan the rest of the stroke changes, invalid samples).
#include "penshape/core/ink_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "penshape/core/base.hpp"
#include "penshape/core/ink.hpp"
#include "support/dollar1.hpp"
#include "test_data.hpp"

namespace penshape {
namespace {

constexpr std::size_t kChunk = kInkChunkSegments;

void expect_same_polygon(const InkPolygon& a, const InkPolygon& b) {
  EXPECT_EQ(a.hausdorff_bound, b.hausdorff_bound);
  EXPECT_EQ(a.grid, b.grid);
  EXPECT_EQ(a.disk_vertices, b.disk_vertices);
  ASSERT_EQ(a.region.polygons.size(), b.region.polygons.size());
  for (std::size_t i = 0; i < a.region.polygons.size(); ++i) {
    EXPECT_TRUE(a.region.polygons[i].outer == b.region.polygons[i].outer) << "polygon " << i;
    EXPECT_TRUE(a.region.polygons[i].holes == b.region.polygons[i].holes) << "polygon " << i;
  }
}

// A random walk of n samples (a hand's wobble), radius fixed or varying.
std::vector<InkSample> random_stroke(std::mt19937& rng, std::size_t n, bool vary) {
  std::normal_distribution<double> step(0.0, 0.6);
  std::uniform_real_distribution<double> radius(0.2, 0.5);
  std::vector<InkSample> out;
  out.reserve(n);
  double x = 10, y = 10, dx = 0.4, dy = 0.1;
  for (std::size_t i = 0; i < n; ++i) {
    dx = 0.8 * dx + 0.2 * step(rng);
    dy = 0.8 * dy + 0.2 * step(rng);
    x += dx;
    y += dy;
    out.push_back({x, y, vary ? radius(rng) : 0.5});
  }
  return out;
}

// Feeds `samples` in batches of `batch`, building every chunk they complete as it goes (as the
// daemon does while the pen is down), then Q of `whole`.
InkPolygon built_ahead(const std::vector<InkSample>& samples, std::size_t batch,
                       const std::vector<InkSample>& whole, const InkOptions& options,
                       std::size_t* chunks = nullptr) {
  InkBuilder builder(options);
  for (std::size_t i = 0; i < samples.size(); i += batch) {
    const auto end =
        samples.begin() + static_cast<std::ptrdiff_t>(std::min(i + batch, samples.size()));
    builder.add(std::vector<InkSample>(samples.begin() + static_cast<std::ptrdiff_t>(i), end));
    while (builder.build_next()) {
    }
  }
  if (chunks != nullptr) *chunks = builder.built_chunks();
  return builder.polygon(whole);
}

TEST(InkBuilder, RandomStrokesEqualOneShot) {
  std::mt19937 rng(26);
  const InkOptions options{.radius_mm = 0.5};
  for (const std::size_t n : {1U, 2U, 3U, 64U, 65U, 66U, 129U, 130U, 300U, 1000U}) {
    for (const bool vary : {false, true}) {
      SCOPED_TRACE(std::to_string(n) + (vary ? " samples, varying radius" : " samples"));
      const std::vector<InkSample> s = random_stroke(rng, n, vary);
      std::size_t chunks = 0;
      expect_same_polygon(built_ahead(s, 7, s, options, &chunks), ink_polygon(s, options));
      EXPECT_EQ(chunks, n <= 1 ? 0 : (n - 1) / kChunk); // every complete chunk built ahead
    }
  }
}

TEST(InkBuilder, PenUpMidChunkAndOnAChunkEnd) {
  std::mt19937 rng(1);
  const InkOptions options{.radius_mm = 0.5};
  const std::vector<InkSample> s = random_stroke(rng, 3 * kChunk + 1, false);
  for (const std::size_t up : {kChunk + 1, kChunk + kChunk / 2, 2 * kChunk + 1, 3 * kChunk + 1}) {
    SCOPED_TRACE(up);
    const std::vector<InkSample> drawn(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(up));
    std::size_t chunks = 0;
    expect_same_polygon(built_ahead(drawn, 1, drawn, options, &chunks),
                        ink_polygon(drawn, options));
    EXPECT_EQ(chunks, (up - 1) / kChunk);
  }
}

// Work ahead is only reused for the same samples: a changed one, or fewer samples than were fed
// (a hold's stroke drawn before the pen came to rest), gives Q of the samples asked for.
TEST(InkBuilder, ChangedOrShorterStrokeIsRebuilt) {
  std::mt19937 rng(2);
  const InkOptions options{.radius_mm = 0.5};
  const std::vector<InkSample> s = random_stroke(rng, 200, false);
  std::vector<InkSample> changed = s;
  changed[10].x += 3.0;
  expect_same_polygon(built_ahead(s, 5, changed, options), ink_polygon(changed, options));
  const std::vector<InkSample> shorter(s.begin(), s.begin() + 100);
  expect_same_polygon(built_ahead(s, 5, shorter, options), ink_polygon(shorter, options));
}

// A wider radius later in the stroke needs a finer disk polygon: the chunks built with the
// coarser one are rebuilt.
TEST(InkBuilder, PlanChangedByTheRestOfTheStroke) {
  std::mt19937 rng(3);
  const InkOptions options{.radius_mm = 2.0};
  std::vector<InkSample> s = random_stroke(rng, 3 * kChunk, true); // radii 0.2 to 0.5
  for (std::size_t i = 2 * kChunk + 10; i < s.size(); ++i)
    s[i].radius = 1.5 + 0.01 * static_cast<double>(i % 7);
  expect_same_polygon(built_ahead(s, 3, s, options), ink_polygon(s, options));
}

TEST(InkBuilder, InvalidSampleThrowsAsOneShot) {
  std::mt19937 rng(4);
  const InkOptions options{.radius_mm = 0.5};
  std::vector<InkSample> s = random_stroke(rng, 150, false);
  s[70].x = std::nan("");
  EXPECT_THROW((void)ink_polygon(s, options), InvalidInput);
  EXPECT_THROW((void)built_ahead(s, 4, s, options), InvalidInput);
  EXPECT_THROW((void)InkBuilder(options).polygon({}), InvalidInput);
}

// The final union given the built chunks' pieces while the pen was down is spent by the first
// polygon() that uses it: a second call builds its union whole, and neither Q holds the other's
// last chunk. A call that cannot use it (fewer samples: a hold's stroke drawn before the pen came
// to rest) leaves it to the next.
TEST(InkBuilder, TheUnionFedAheadIsUsedOnce) {
  std::mt19937 rng(6);
  const InkOptions options{.radius_mm = 0.5};
  const std::vector<InkSample> s = random_stroke(rng, 3 * kChunk + 8, false);
  std::vector<InkSample> moved = s;
  moved.back().x += 50.0; // the last chunk only: the built chunks are reused
  const std::vector<InkSample> shorter(s.begin(), s.begin() + kChunk + 20);
  InkBuilder builder(options);
  builder.add(s);
  while (builder.build_next()) {
  }
  ASSERT_EQ(builder.built_chunks(), 3U);
  expect_same_polygon(builder.polygon(shorter), ink_polygon(shorter, options));
  expect_same_polygon(builder.polygon(moved), ink_polygon(moved, options));
  expect_same_polygon(builder.polygon(s), ink_polygon(s, options));
}

// The work ahead checks each sample once, as it arrives: an invalid sample after a built chunk
// stops the next one (and polygon() throws ink_polygon's error).
TEST(InkBuilder, InvalidSampleAfterABuiltChunkStopsTheWorkAhead) {
  std::mt19937 rng(5);
  const InkOptions options{.radius_mm = 0.5};
  std::vector<InkSample> s = random_stroke(rng, 3 * kChunk, false);
  s[kChunk + 10].y = std::numeric_limits<double>::infinity();
  InkBuilder builder(options);
  builder.add(std::vector<InkSample>(s.begin(), s.begin() + kChunk + 5));
  EXPECT_TRUE(builder.build_next());
  builder.add(std::vector<InkSample>(s.begin() + kChunk + 5, s.end()));
  EXPECT_FALSE(builder.build_next());
  EXPECT_EQ(builder.built_chunks(), 1U);
  EXPECT_THROW((void)builder.polygon(s), InvalidInput);
}

TEST(InkBuilder, RealStrokesEqualOneShot) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/dollar1/s02/medium");
  const InkOptions options{.radius_mm = 3.0}; // pixels as millimetres
  std::size_t strokes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    SCOPED_TRACE(entry.path().filename().string());
    std::vector<InkSample> s;
    for (const PointD& p : test::read_dollar1(entry.path().string())) s.push_back({p.x, p.y, 3.0});
    expect_same_polygon(built_ahead(s, 9, s, options), ink_polygon(s, options));
    ++strokes;
  }
  EXPECT_GT(strokes, 100U);
}

} // namespace
} // namespace penshape
