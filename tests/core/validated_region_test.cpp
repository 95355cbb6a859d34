// ValidatedRegion (issue 26): a region validated once is decided without validating it again,
// with the same answers and the same parameter and limit errors as deconstruct() on the set.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "penshape/core/polygon_io.hpp"
#include "penshape/core/validated_region.hpp"

namespace penshape {
namespace {

const DeconstructParams kParams{30, 15, 2};

// A star of n integer vertices (angles increase: simple), big enough for the validation sweep
// to ask the cancel hook many times.
PolygonSet star(int n) {
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    const double r = i % 2 == 0 ? 1000 : 960;
    ring.push_back({static_cast<int>(std::lround(r * std::cos(a))),
                    static_cast<int>(std::lround(r * std::sin(a)))});
  }
  return {{{ring, {}}}};
}

TEST(ValidatedRegion, RefusesWhatValidationRefusesWithItsMessage) {
  const PolygonSet bowtie{{{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}}};
  std::string expected;
  try {
    validate_region(bowtie);
  } catch (const InvalidInput& e) {
    expected = e.what();
  }
  ASSERT_FALSE(expected.empty());
  try {
    (void)ValidatedRegion::validate(bowtie);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
}

TEST(ValidatedRegion, DecidesAsTheSetDoes) {
  const PolygonSet q = star(400);
  const ValidatedRegion valid = ValidatedRegion::validate(q);
  const DeconstructResult a = deconstruct(q, kParams);
  const DeconstructResult b = deconstruct(valid, kParams);
  EXPECT_EQ(a.answer, b.answer);
  EXPECT_EQ(a.engine, b.engine);
  EXPECT_EQ(to_wkt(a.solution), to_wkt(b.solution));
}

TEST(ValidatedRegion, ParametersAndLimitsAreStillChecked) {
  const ValidatedRegion valid = ValidatedRegion::validate(star(400));
  DeconstructParams bad = kParams;
  bad.precision = bad.tolerance; // not below it
  EXPECT_THROW((void)deconstruct(valid, bad), InvalidInput);
  try {
    (void)deconstruct(valid, kParams, {}, {.max_input_vertices = 100});
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("over the limit of 100"), std::string::npos) << e.what();
  }
  ValidatedRegion spent = ValidatedRegion::validate(star(400));
  const PolygonSet taken = std::move(spent).release();
  EXPECT_EQ(taken.vertex_count(), 400U);
  EXPECT_THROW((void)deconstruct(spent, kParams), InvalidInput); // NOLINT(bugprone-use-after-move)
}

// Observed through the cancel hook, which validation asks every 256 sweep events: deciding a
// ValidatedRegion asks it exactly validation's count fewer times than deciding the set.
TEST(ValidatedRegion, TheRegionIsValidatedOnce) {
  const PolygonSet q = star(4000);
  int calls = 0;
  const CancelHook count = [&calls] {
    ++calls;
    return false;
  };
  validate_region(q, 200'000, count);
  const int validation = calls;
  ASSERT_GT(validation, 0);
  calls = 0;
  (void)deconstruct(q, kParams, count);
  const int whole = calls;
  const ValidatedRegion valid = ValidatedRegion::validate(q);
  calls = 0;
  (void)deconstruct(valid, kParams, count);
  EXPECT_EQ(whole - calls, validation);
}

} // namespace
} // namespace penshape
