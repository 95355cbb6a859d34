#pragma once
// A seeded random source whose numbers are the same on every platform and standard library
// (std::normal_distribution and friends are not), so generated test data is reproducible.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace penshape::gen {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1): the top 53 bits of one draw.
  double unit() { return static_cast<double>(engine_() >> 11U) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // Uniform integer in [lo, hi].
  int integer(int lo, int hi) {
    const auto span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo + 1);
    return static_cast<int>(lo + static_cast<std::int64_t>(engine_() % span));
  }
  bool chance(double p) { return unit() < p; }
  // Box-Muller: a standard normal draw.
  double normal(double mean = 0.0, double sd = 1.0) {
    const double u = 1.0 - unit(); // (0, 1]
    const double v = unit();
    return mean + sd * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
  }

 private:
  std::mt19937_64 engine_; // its output sequence is fixed by the standard
};

} // namespace penshape::gen
