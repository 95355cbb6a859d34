#include "penshape/core/disk_approximation.hpp"

#include <string>

#include "penshape/core/base.hpp"

namespace penshape {
namespace {

// Smallest integer z >= 0 with z² >= x, for a rational x >= 0.
mpz_class ceil_sqrt(const Rational& x) {
  mpz_class n;
  mpz_cdiv_q(n.get_mpz_t(), x.get_num_mpz_t(), x.get_den_mpz_t()); // ceil(x)
  mpz_class z = sqrt(n);
  while (Rational(z * z) < x) ++z;
  // Decrease while still sufficient, in case ceil(x) overshot by a whole square.
  while (z > 0 && Rational((z - 1) * (z - 1)) >= x) --z;
  return z;
}

} // namespace

std::size_t disk_approximation_z(const Rational& a, const Rational& b) {
  // z >= b / sqrt(b² - a²)  <=>  z² >= b² / (b² - a²).
  const Rational ratio = (b * b) / (b * b - a * a);
  const mpz_class z = ceil_sqrt(ratio);
  return z.fits_ulong_p() ? static_cast<std::size_t>(z.get_ui()) : static_cast<std::size_t>(-1);
}

Ring disk_approximation(const Rational& a, const Rational& b, std::size_t max_vertices) {
  if (sgn(a) < 0 || b <= a) {
    throw InvalidInput("disk approximation needs 0 <= a < b, got a = " + a.get_str() +
                       ", b = " + b.get_str());
  }
  std::size_t z = disk_approximation_z(a, b);
  if (z < 2) z = 2; // at least a square rotated to have 8 vertices keeps the shape round-ish
  if (z > max_vertices / 4) {
    throw InvalidInput("disk approximation between radii " + std::to_string(a.get_d()) + " and " +
                       std::to_string(b.get_d()) + " needs " + std::to_string(4 * z) +
                       " vertices, over the limit of " + std::to_string(max_vertices) +
                       " (precision too fine for the radius)");
  }
  // First quadrant: Q_{i/z}, i = 0..z-1 (i = z gives (0, b), the next quadrant's start).
  std::vector<ExactPoint> quadrant;
  quadrant.reserve(z);
  const Rational zq(static_cast<unsigned long>(z));
  for (std::size_t i = 0; i < z; ++i) {
    const Rational t = Rational(static_cast<unsigned long>(i)) / zq;
    const Rational denom = 1 + t * t;
    quadrant.push_back({b * (1 - t * t) / denom, b * 2 * t / denom});
  }
  Ring ring;
  ring.reserve(4 * z);
  // Rotating by 90° maps (x, y) to (-y, x): exact, and keeps counterclockwise order.
  for (int q = 0; q < 4; ++q) {
    for (const auto& p : quadrant) {
      switch (q) {
        case 0:
          ring.push_back(p);
          break;
        case 1:
          ring.push_back({-p.y, p.x});
          break;
        case 2:
          ring.push_back({-p.x, -p.y});
          break;
        default:
          ring.push_back({p.y, -p.x});
          break;
      }
    }
  }
  return ring;
}

bool is_disk_approximation(const Ring& ring, const Rational& a, const Rational& b) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const ExactPoint& p = ring[i];
    const ExactPoint& q = ring[(i + 1) % n];
    if (p.x * p.x + p.y * p.y > b * b) return false;
    // Signed distance of the origin to the edge line, squared: cross(p, q)² / |q - p|².
    // Counterclockwise and convex: cross(p, q) > 0 puts the origin on the inner side.
    const Rational cross = p.x * q.y - p.y * q.x;
    if (sgn(cross) <= 0) return false;
    const Rational dx = q.x - p.x;
    const Rational dy = q.y - p.y;
    if (cross * cross < a * a * (dx * dx + dy * dy)) return false;
  }
  return true;
}

} // namespace penshape
