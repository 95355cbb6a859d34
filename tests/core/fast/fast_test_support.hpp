#pragma once
// Test-only helpers for the fast engine: a tiny reader for the x-y polygon files (the official
// parser belongs to the I/O code) and an independent dense-sampling checker of YES solutions in
// plain doubles (no engine code): it evaluates the two inclusions of Proposition 3 at many points.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "penshape/core/polygon_set.hpp"
#include "test_data.hpp"

namespace penshape::fast_test {

// "12", "-3.25", "1/3" as exact rationals.
inline Rational parse_rational(const std::string& token) {
  const auto slash = token.find('/');
  if (slash != std::string::npos) {
    Rational v(mpz_class(token.substr(0, slash)), mpz_class(token.substr(slash + 1)));
    v.canonicalize();
    return v;
  }
  std::string digits;
  int scale = 0;
  bool after_point = false;
  for (const char c : token) {
    if (c == '.') {
      after_point = true;
    } else {
      digits.push_back(c);
      if (after_point) ++scale;
    }
  }
  Rational v(mpz_class(digits), 1);
  mpz_class den;
  mpz_ui_pow_ui(den.get_mpz_t(), 10, static_cast<unsigned long>(scale));
  v /= Rational(den);
  v.canonicalize();
  return v;
}

inline PolygonSet read_polygon_file(const std::string& path) {
  std::ifstream in(path);
  PolygonWithHoles poly;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string x, y;
    if (ls >> x >> y) poly.outer.push_back({parse_rational(x), parse_rational(y)});
  }
  PolygonSet set;
  if (!poly.outer.empty()) set.polygons.push_back(std::move(poly));
  normalize_orientation(set);
  return set;
}

// A star-shaped (hence simple) random polygon around the origin, counterclockwise.
inline PolygonSet random_star_polygon(std::mt19937& rng, int n, double radius) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), scale(0.4, 1.0);
  std::vector<double> angles(static_cast<std::size_t>(n));
  for (double& a : angles) a = angle(rng);
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  PolygonWithHoles poly;
  for (const double a : angles) {
    const double r = radius * scale(rng);
    // Rounded to 1/1024 like tablet coordinates: small dyadic rationals.
    poly.outer.push_back(exact(PointD{std::round(r * std::cos(a) * 1024) / 1024,
                                      std::round(r * std::sin(a) * 1024) / 1024}));
  }
  PolygonSet set;
  set.polygons.push_back(std::move(poly));
  normalize_orientation(set);
  return set;
}

// ---- independent double-precision geometry ----

struct Pt {
  double x, y;
};
using Rings = std::vector<std::vector<Pt>>;

inline Rings to_rings(const PolygonSet& set) {
  Rings rings;
  for (const auto& poly : set.polygons) {
    std::vector<Pt> outer;
    for (const auto& p : poly.outer) outer.push_back({p.x.get_d(), p.y.get_d()});
    rings.push_back(outer);
    for (const auto& hole : poly.holes) {
      std::vector<Pt> h;
      h.reserve(hole.size());
      for (const auto& p : hole) h.push_back({p.x.get_d(), p.y.get_d()});
      rings.push_back(h);
    }
  }
  return rings;
}

inline double seg_dist(Pt p, Pt a, Pt b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// Even-odd rule: holes are separate rings.
inline bool inside(const Rings& rings, Pt p) {
  bool in = false;
  for (const auto& ring : rings) {
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const Pt a = ring[i], b = ring[j];
      if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
        in = !in;
      }
    }
  }
  return in;
}

inline double boundary_dist(const Rings& rings, Pt p) {
  double best = 1e300;
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      best = std::min(best, seg_dist(p, ring[i], ring[(i + 1) % ring.size()]));
    }
  }
  return best;
}

inline double region_dist(const Rings& rings, Pt p) {
  return inside(rings, p) ? 0.0 : boundary_dist(rings, p);
}

struct YesCheck {
  double q_excess = -1e300; // max over Q samples of d(x, P) - (r + eps); must be <= 0
  double p_excess = -1e300; // max over offset(P, r) samples of d(y, Q) - eps; must be <= 0
  std::size_t samples = 0;
};

// Samples: both boundaries densely (spacing h), the r-offset curves of P's edges and vertices
// (spacing h), and a grid over the common box (spacing h, at most ~150 x 150 points).
inline YesCheck check_yes(const PolygonSet& q_set, const PolygonSet& p_set, double r, double eps,
                          double h) {
  const Rings q = to_rings(q_set), p = to_rings(p_set);
  YesCheck out;
  auto at_q = [&](Pt x) {
    out.q_excess = std::max(out.q_excess, region_dist(p, x) - (r + eps));
    ++out.samples;
  };
  auto at_offset = [&](Pt y) {
    if (region_dist(p, y) > r) return;
    out.p_excess = std::max(out.p_excess, region_dist(q, y) - eps);
    ++out.samples;
  };
  auto along = [&](const Rings& rings, auto&& f) {
    for (const auto& ring : rings) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Pt a = ring[i], b = ring[(i + 1) % ring.size()];
        const int k = std::max(1, static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / h));
        for (int s = 0; s < k; ++s) {
          const double t = static_cast<double>(s) / k;
          f(a, b, Pt{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
        }
      }
    }
  };
  along(q, [&](Pt, Pt, Pt x) { at_q(x); });
  // r-offset curves of P: both sides of each edge and circles around the vertices.
  along(p, [&](Pt a, Pt b, Pt x) {
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const Pt n{(b.y - a.y) / len, -(b.x - a.x) / len};
    at_offset({x.x + r * n.x, x.y + r * n.y});
    at_offset({x.x - r * n.x, x.y - r * n.y});
  });
  const int circle = std::max(16, static_cast<int>(2 * M_PI * r / h));
  for (const auto& ring : p) {
    for (const Pt v : ring) {
      for (int s = 0; s < circle; ++s) {
        const double a = 2 * M_PI * s / circle;
        at_offset({v.x + r * std::cos(a), v.y + r * std::sin(a)});
      }
    }
  }
  double min_x = 1e300, min_y = 1e300, max_x = -1e300, max_y = -1e300;
  for (const auto& ring : q) {
    for (const Pt v : ring) {
      min_x = std::min(min_x, v.x - r - eps);
      min_y = std::min(min_y, v.y - r - eps);
      max_x = std::max(max_x, v.x + r + eps);
      max_y = std::max(max_y, v.y + r + eps);
    }
  }
  // The area grid is capped at about 150 x 150 points (boundaries above are sampled at h).
  const double g = std::max(h, std::max(max_x - min_x, max_y - min_y) / 150.0);
  for (double y = min_y; y <= max_y; y += g) {
    for (double x = min_x; x <= max_x; x += g) {
      if (inside(q, {x, y})) at_q({x, y});
      at_offset({x, y});
    }
  }
  return out;
}

} // namespace penshape::fast_test
