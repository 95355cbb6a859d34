// The ink polygon's exact coordinates (core/src/ink/ink_chunks.hpp on_grid): an integer number of
// grid units in mm, made by a shift, is the exact product by the grid (value and GMP's canonical
// form), for grids far below and above a millimetre and integers up to Clipper's range.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "ink/ink_chunks.hpp"
#include "penshape/core/base.hpp"

namespace penshape {
namespace {

TEST(InkGrid, OnGridIsTheExactProductByTheGrid) {
  std::mt19937_64 rng(26);
  std::vector<std::int64_t> values{
      0, 1, -1, 2, -2, 1024, -3072, (std::int64_t{1} << 62) - 1, -(std::int64_t{1} << 62)};
  for (int i = 0; i < 200; ++i) {
    values.push_back(static_cast<std::int64_t>(rng() >> static_cast<unsigned>(2 + i % 60)) *
                     (i % 2 == 0 ? 1 : -1));
  }
  for (int e = -60; e <= 20; ++e) {
    const double grid = std::ldexp(1.0, e);
    for (const std::int64_t v : values) {
      const Rational expected = Rational(mpz_class(static_cast<long>(v))) * exact(grid);
      const Rational got = ink_detail::on_grid(v, grid);
      ASSERT_TRUE(got == expected) << v << " at grid 2^" << e;
      ASSERT_EQ(got.get_str(), expected.get_str()) << v << " at grid 2^" << e;
    }
  }
}

} // namespace
} // namespace penshape
