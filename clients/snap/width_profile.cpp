// A certificate for the widths drawn and written (see width_profile.hpp).
#include "width_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penshape::snap {
namespace {

double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

// max |ρ - r| over `radii`, each difference rounded up (a double subtraction errs by half an ulp;
// it is exact when 0).
double spread(const std::vector<double>& radii, double r) {
  double out = 0;
  for (const double rho : radii) {
    const double d = std::abs(rho - r);
    out = std::max(out, d > 0 ? up(d) : 0.0);
  }
  return out;
}

} // namespace

bool certify_width_profile(Recognition& r, const std::vector<double>& written,
                           const std::vector<double>& drawn) {
  Certificate& c = r.certificate;
  const double out = spread(written, c.pen_radius);
  const double in = c.method == "path" ? spread(drawn, c.pen_radius) : 0.0;
  if (out > 0 || in > 0) {
    c.bound = up(up(c.bound + out) + in);
    c.method += "+width_profile";
  }
  if (!(c.bound <= c.epsilon)) c.certified = false;
  return c.certified;
}

} // namespace penshape::snap
