// Random inputs with features at and below the fast engine's grid scale (soundness_generator.hpp).
#include "soundness_generator.hpp"

#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace penshape::test {
namespace {

// Uniform doubles from the generator's raw 64-bit output (std distributions differ between
// standard libraries; this does not).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed * 0x9E3779B97F4A7C15ULL + 12345U) {}
  double uniform(double lo, double hi) {
    const double u = static_cast<double>(g_() >> 11U) * 0x1.0p-53;
    return lo + (hi - lo) * u;
  }
  int pick(int n) { return static_cast<int>(g_() % static_cast<std::uint64_t>(n)); }
  // A thickness between 1e-7 and 1e-3, log-uniform: below and above a grid unit.
  double thickness() { return std::pow(10.0, uniform(-7.0, -3.0)); }

 private:
  std::mt19937_64 g_;
};

using Pts = std::vector<std::pair<double, double>>;

Ring ring_of(const Pts& pts) {
  Ring r;
  for (const auto& [x, y] : pts) r.push_back({Rational(x), Rational(y)});
  return r;
}

void add_polygon(PolygonSet& q, const Pts& outer, const Pts& hole = {}) {
  PolygonWithHoles p;
  p.outer = ring_of(outer);
  if (!hole.empty()) p.holes.push_back(ring_of(hole));
  q.polygons.push_back(std::move(p));
}

Pts rectangle(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}

// A thin x-monotone ring of length `len` and thickness about t (k >= 2 stations), rotated by
// `angle` and moved to (x0, y0): counterclockwise, simple before rounding.
Pts thin_ring(Rng& rng, double len, double t, int k, double angle, double x0, double y0) {
  std::vector<double> xs{0.0};
  for (int i = 1; i + 1 < k; ++i) xs.push_back(len * (i + rng.uniform(-0.3, 0.3)) / (k - 1));
  xs.push_back(len);
  Pts local;
  for (const double x : xs) local.push_back({x, -t * rng.uniform(0.2, 1.0)});
  for (auto it = xs.rbegin(); it != xs.rend(); ++it)
    local.push_back({*it, t * rng.uniform(0.2, 1.0)});
  const double c = std::cos(angle), s = std::sin(angle);
  Pts out;
  for (const auto& [x, y] : local) out.push_back({x0 + c * x - s * y, y0 + s * x + c * y});
  return out;
}

// A thin triangle: base of width t at (x0, y0), apex `len` away along `angle`.
Pts sliver_triangle(double len, double t, double angle, double x0, double y0) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {{x0 + s * t / 2, y0 - c * t / 2},
          {x0 + c * len, y0 + s * len},
          {x0 - s * t / 2, y0 + c * t / 2}};
}

Pts subdivided_square(Rng& rng, double side) {
  const Pts corners = rectangle(0, 0, side, side);
  Pts out;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto [x0, y0] = corners[k];
    const auto [x1, y1] = corners[(k + 1) % 4];
    const int n = 2 + rng.pick(20);
    for (int i = 0; i < n; ++i) {
      const double f = static_cast<double>(i) / n; // collinear: axis-parallel edges
      out.push_back({x0 + (x1 - x0) * f, y0 + (y1 - y0) * f});
    }
  }
  return out;
}

void build(int kind, Rng& rng, SoundnessCase& c, const Rational& r, const Rational& e) {
  const double t = rng.thickness();
  // Features within about r + eps of the body: YES and NO both occur.
  const double gap = rng.uniform(0.01, 1.0);
  const double len = rng.uniform(0.05, 2.5);
  const double angle = rng.uniform(-0.6, 0.6);
  PolygonSet& q = c.q;
  switch (kind) {
    case 0: // a separate sliver beside a square
      c.kind = "separate sliver";
      add_polygon(q, rectangle(0, 0, 10, 10));
      add_polygon(q, thin_ring(rng, len, t, 2, angle, 10 + gap, rng.uniform(0, 10)));
      break;
    case 1: { // a needle on a rectangle's side
      c.kind = "needle touching";
      const double y = rng.uniform(1, 9);
      add_polygon(
          q, {{0, 0}, {10, 0}, {10, y - t / 2}, {10 + len, y}, {10, y + t / 2}, {10, 10}, {0, 10}});
      break;
    }
    case 2: // the false YES, jittered: a triangle just beside a square
      c.kind = "needle apart";
      add_polygon(q, rectangle(0, 0, 10, 10));
      add_polygon(q, sliver_triangle(rng.pick(4) == 0 ? 19.5 : len, t, 0.0,
                                     10 + rng.uniform(1e-6, 0.6), rng.uniform(0.5, 9.5)));
      break;
    case 3: { // the false NO, jittered: a needle above a strip
      c.kind = "needle above a strip";
      const double h = rng.uniform(0.5, 1.2);
      add_polygon(q, rectangle(0, 0, 20, h));
      add_polygon(q, thin_ring(rng, rng.uniform(2, 19), t, 2, 0.0, rng.uniform(0, 1),
                               h + rng.uniform(0.2, 0.7)));
      break;
    }
    case 4: // a near-degenerate ring with several stations
      c.kind = "near-degenerate ring";
      add_polygon(q, rectangle(0, 0, 10, 10));
      add_polygon(q, thin_ring(rng, len, t, 3 + rng.pick(6), angle, 10 + gap, rng.uniform(0, 10)));
      break;
    case 5: // a twisted thin ring: as thick as a grid unit, so rounding may cross its chains
      c.kind = "twisted thin ring";
      add_polygon(q, rectangle(0, 0, 10, 10));
      add_polygon(q, thin_ring(rng, len, rng.uniform(1e-5, 2e-4), 4 + rng.pick(8), angle, 10 + gap,
                               rng.uniform(0, 10)));
      break;
    case 6: // a thin hole (a slit) inside a square
      c.kind = "thin hole";
      add_polygon(
          q, rectangle(0, 0, 10, 10),
          thin_ring(rng, rng.uniform(0.5, 7), t, 2 + rng.pick(4), angle, 1.5, rng.uniform(3, 7)));
      break;
    case 7: // collinear runs on a square, and a sliver
      c.kind = "collinear runs";
      add_polygon(q, subdivided_square(rng, 10));
      add_polygon(q, thin_ring(rng, len, t, 2, angle, 10 + gap, rng.uniform(0, 10)));
      break;
    case 8: { // a rectangle at the ε-band's edge 2(r - eps) (+/- 2^-30 or exact), and a sliver
      c.kind = "tie at the band";
      const double w = 2 * Rational(r - e).get_d() + (rng.pick(3) - 1) * 0x1.0p-30;
      add_polygon(q, rectangle(0, 0, w, 12));
      add_polygon(q, thin_ring(rng, len, t, 2, angle, w + gap, rng.uniform(0, 12)));
      break;
    }
    default: // a thin convex sliver alone: the convex path
      c.kind = "convex sliver";
      add_polygon(q, rng.pick(2) == 0 ? sliver_triangle(rng.uniform(0.5, 20), t, angle, 0, 0)
                                      : thin_ring(rng, rng.uniform(0.5, 20), t, 2, angle, 0, 0));
      break;
  }
}

} // namespace

int soundness_kind_count() { return 10; }

SoundnessCase make_soundness_case(std::uint64_t seed) {
  Rng rng(seed);
  SoundnessCase c;
  const Rational r(1);
  const Rational e = std::vector<Rational>{Rational(1, 2), Rational(1, 4),
                                           Rational(3, 8)}[static_cast<std::size_t>(rng.pick(3))];
  c.params = {r, e, e / 8, EngineKind::kFast};
  build(static_cast<int>(seed % static_cast<std::uint64_t>(soundness_kind_count())), rng, c, r, e);
  return c;
}

} // namespace penshape::test
