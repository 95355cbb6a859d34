// The hand and the pen: what turns an ideal path into logged samples (see pen_model.hpp).
#include "pen_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "stroke_measurements.hpp"

namespace penshape::gen {
namespace {

double dist(Pt a, Pt b) { return std::hypot(a.x - b.x, a.y - b.y); }
Pt lerp(Pt a, Pt b, double u) { return {a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)}; }

// Turning angle at each point over a window of neighbours: where the pen must slow down.
std::vector<double> bend(const std::vector<Pt>& p, std::size_t window) {
  std::vector<double> out(p.size(), 0.0);
  for (std::size_t i = window; i + window < p.size(); ++i) {
    const Pt a = p[i - window], b = p[i], c = p[i + window];
    const double h1 = std::atan2(b.y - a.y, b.x - a.x), h2 = std::atan2(c.y - b.y, c.x - b.x);
    double d = std::fabs(h2 - h1);
    if (d > std::numbers::pi) d = 2 * std::numbers::pi - d;
    out[i] = d;
  }
  return out;
}

} // namespace

std::vector<Pt> round_corners(const std::vector<Pt>& path, double radius) {
  if (path.size() < 3) return path;
  std::vector<Pt> out{path.front()};
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const Pt a = path[i - 1], v = path[i], b = path[i + 1];
    const double r = std::min({radius, 0.45 * dist(a, v), 0.45 * dist(v, b)});
    const Pt p = lerp(v, a, r / std::max(dist(a, v), 1e-9));
    const Pt q = lerp(v, b, r / std::max(dist(v, b), 1e-9));
    for (int k = 0; k <= 8; ++k) { // quadratic Bezier p -> v -> q
      const double u = k / 8.0;
      out.push_back(lerp(lerp(p, v, u), lerp(v, q, u), u));
    }
  }
  out.push_back(path.back());
  return out;
}

std::vector<Pt> resample(const std::vector<Pt>& path, double step) {
  std::vector<Pt> out{path.front()};
  double carry = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double len = dist(path[i - 1], path[i]);
    double s = step - carry;
    for (; s < len; s += step) out.push_back(lerp(path[i - 1], path[i], s / len));
    carry = len - (s - step);
  }
  if (dist(out.back(), path.back()) > 1e-9) out.push_back(path.back());
  return out;
}

double wobble_rms(double diagonal, double speed) {
  const double radius = diagonal / (2.0 * std::numbers::sqrt2);
  const double w =
      measured::kWobble0 + measured::kWobblePerRadius * radius + measured::kWobblePerSpeed * speed;
  return std::max(w, 0.5 * measured::kTremor);
}

void add_wobble(std::vector<Pt>& path, double rms, double diagonal, Rng& rng) {
  if (path.size() < 3) return;
  double total = 0.0;
  std::vector<double> s{0.0};
  for (std::size_t i = 1; i < path.size(); ++i) s.push_back(total += dist(path[i - 1], path[i]));
  // Three waves of 1..4 cycles per circumference; their amplitudes sum to the wanted RMS.
  const double circumference = std::numbers::pi * diagonal / std::numbers::sqrt2;
  double freq[3], phase[3], amp[3], power = 0.0;
  for (int k = 0; k < 3; ++k) {
    freq[k] = rng.uniform(1.0, 4.0);
    phase[k] = rng.uniform(0.0, 2 * std::numbers::pi);
    amp[k] = rng.uniform(0.3, 1.0);
    power += 0.5 * amp[k] * amp[k];
  }
  const double norm = rms / std::sqrt(power);
  const std::vector<Pt> in = path;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Pt a = in[i == 0 ? 0 : i - 1], b = in[std::min(i + 1, in.size() - 1)];
    const double len = std::max(dist(a, b), 1e-9);
    double off = 0.0;
    for (int k = 0; k < 3; ++k)
      off += amp[k] * std::sin(2 * std::numbers::pi * freq[k] * s[i] / circumference + phase[k]);
    path[i].x += norm * off * -(b.y - a.y) / len;
    path[i].y += norm * off * (b.x - a.x) / len;
  }
}

void add_hook(std::vector<Pt>& path, double length, Rng& rng) {
  if (path.size() < 2) return;
  const Pt a = path[path.size() - 2], b = path.back();
  const double heading = std::atan2(b.y - a.y, b.x - a.x);
  // Draws named one by one: operands' evaluation order is unspecified, and compilers differ.
  const double sign = rng.chance(0.5) ? 1 : -1;
  const double turn = sign * rng.uniform(1.6, 2.6);
  for (int k = 1; k <= 6; ++k) { // a tight curve turning by `turn`
    const double h = heading + turn * k / 6.0;
    const Pt last = path.back();
    path.push_back({last.x + length / 6.0 * std::cos(h), last.y + length / 6.0 * std::sin(h)});
  }
}

double pen_speed(Speed speed, Rng& rng) {
  const double mean = speed == Speed::kSlow     ? measured::kSpeedSlow
                      : speed == Speed::kMedium ? measured::kSpeedMedium
                                                : measured::kSpeedFast;
  return mean * rng.uniform(0.75, 1.25);
}

GenStroke sample_pen(const std::vector<Pt>& path, double speed, double t0, Rng& rng) {
  const std::vector<Pt> p = resample(path, 0.5);
  const std::vector<double> turn = bend(p, 6);
  // Time at each dense point: slower in bends and over the first and last tenth.
  std::vector<double> time{0.0};
  const double n = static_cast<double>(p.size());
  for (std::size_t i = 1; i < p.size(); ++i) {
    const double f = static_cast<double>(i) / n;
    const double ends = std::clamp(std::min(f, 1.0 - f) * 10.0, 0.35, 1.0);
    const double v = ends / (1.0 + 2.5 * turn[i]);
    time.push_back(time.back() + dist(p[i - 1], p[i]) / v);
  }
  const double scale = (0.5 * (n - 1) / speed) / std::max(time.back(), 1e-9);
  GenStroke out;
  std::size_t j = 0;
  const double duration = time.back() * scale;
  for (double t = 0.0;; t += measured::kSampleInterval * rng.uniform(0.8, 1.2)) {
    const bool last =
        t >= duration - 0.002; // the last sample at the end, >= 2 ms after the one before
    const double tt = last ? duration : t;
    while (j + 2 < p.size() && time[j + 1] * scale < tt) ++j;
    const double span = (time[j + 1] - time[j]) * scale;
    const Pt q =
        lerp(p[j], p[j + 1], span > 0 ? std::clamp((tt - time[j] * scale) / span, 0.0, 1.0) : 1.0);
    const double x = std::round(q.x + rng.normal(0.0, measured::kTremor / std::numbers::sqrt2));
    const double y = std::round(q.y + rng.normal(0.0, measured::kTremor / std::numbers::sqrt2));
    out.points.push_back({x, y, t0 + tt});
    const double f = duration > 0 ? tt / duration : 1.0;
    const double ramp = std::clamp(std::min(f, 1.0 - f) * 8.0, 0.25, 1.0);
    out.pressure.push_back(std::clamp(0.7 * ramp + rng.normal(0.0, 0.03), 0.05, 1.0));
    if (last) break;
  }
  return out;
}

} // namespace penshape::gen
