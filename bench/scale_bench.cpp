// Scale of deconstruction and of its independent check (issue 15): wavy star polygons of 10,000,
// 50,000 and 200,000 vertices (generated here, deterministic), r = w/30, eps = r/2,
// delta = eps/8. Prints input validation alone, the whole deconstruct() call (validation + fast
// engine, no simplification) against the 1 s target at 200k, and `penshape verify`'s checker.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/verify.hpp"

namespace {

// A star-shaped ring: increasing angles, so simple by construction.
penshape::PolygonSet wavy_star(int n) {
  std::mt19937 rng(static_cast<unsigned>(n));
  std::uniform_real_distribution<double> jitter(0.0, 0.8);
  std::uniform_real_distribution<double> bump(0.0, 3.0);
  penshape::Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + jitter(rng)) / n;
    const double r = 1000 + 40 * std::sin(7 * a) + bump(rng);
    ring.push_back(penshape::exact(penshape::PointD{std::round(r * std::cos(a) * 1024) / 1024,
                                                    std::round(r * std::sin(a) * 1024) / 1024}));
  }
  return {{{ring, {}}}};
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

int main() {
  std::printf("wavy star, r = w/30, eps = r/2, delta = eps/8 (fast engine, no simplification)\n");
  std::printf("%8s | %13s | %9s %15s %7s | %10s %9s\n", "vertices", "validation ms", "answer",
              "deconstruct ms", "target", "verify ms", "verdict");
  for (const int n : {10'000, 50'000, 200'000}) {
    const penshape::PolygonSet q = wavy_star(n);
    auto t0 = std::chrono::steady_clock::now();
    penshape::validate_region(q);
    const double validation = ms_since(t0);
    const penshape::Rational r(2080 / 30);
    const penshape::DeconstructParams params{r, r / 2, r / 16};
    t0 = std::chrono::steady_clock::now();
    const penshape::DeconstructResult res = penshape::deconstruct(q, params);
    const double decision = ms_since(t0);
    t0 = std::chrono::steady_clock::now();
    const penshape::VerifyReport rep = penshape::verify_deconstruction(
        q, {res.answer, r, r / 2, r / 16, res.solution, res.no_witness});
    const double check = ms_since(t0);
    std::printf("%8d | %13.1f | %9s %15.1f %7s | %10.1f %9s\n", n, validation,
                penshape::to_string(res.answer), decision,
                n == 200'000 ? (decision <= 1000 ? "<=1 s" : ">1 s !") : "", check,
                penshape::to_string(rep.status));
  }
  return 0;
}
