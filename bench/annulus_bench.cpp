// Annulus placement benchmark: minimum-width annulus and max-cover, translation and
// translation + rotation, both outer offsets (round and linearized), n = 100 and 1,000 points,
// m = 4..64 template vertices, each beside a baseline in the same run where it finishes in
// reasonable time:
//   min width (translation):  bisection on the plain max-cover sweep without buckets (count == n)
//   max cover (translation):  the anchored sweep without buckets (Fig. 3 without Section 3.2's
//                             grid)
//   min width (rotation):     linearized: 1-degree angle sampling with the translation algorithm
//                             (approximate); round: branch and bound over the angle with the
//                             translation solver (RotationMethod::kAngleSearch, certified)
//   max cover (rotation):     target: branch and bound over (tx, ty, theta) cells; baseline:
//                             linearized: the exact rotation-diagram sweep (n^3 m^2); round:
//                             branch and bound over the angle with translation sweeps, stopped
//                             after 60 sweeps (its certified k/ub at that point)
//   cover-field:              max cover over points spread far beyond one template, with and
//                             without the bucket grid
// Results: delta=upper (gap upper-lower when the certified interval is not closed), k=covered/ub.
// Usage: annulus_bench [--json] [--quick] [--field-only]   (--quick: n = 100 only)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "penshape/core/annulus/rotation.hpp"
#include "penshape/core/annulus/translation.hpp"

namespace {

using namespace penshape;
using namespace penshape::annulus;

// Regular-ish convex m-gon of radius 100 (slightly perturbed so it is not symmetric).
std::vector<PointD> make_template(std::size_t m) {
  std::vector<PointD> v;
  for (std::size_t k = 0; k < m; ++k) {
    const double a = 2 * std::numbers::pi *
                     (static_cast<double>(k) + 0.2 * std::sin(3.0 * static_cast<double>(k))) /
                     static_cast<double>(m);
    v.push_back({100 * std::cos(a), 70 * std::sin(a)});
  }
  return v;
}

// Points near the boundary (noise +-4) of the template rotated by 0.3 rad and moved, with a
// fraction of outliers.
std::vector<PointD> make_points(const std::vector<PointD>& poly, std::size_t n, unsigned seed,
                                double outliers) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double c = std::cos(0.3), s = std::sin(0.3);
  std::vector<PointD> pts;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = static_cast<std::size_t>(u(rng) * static_cast<double>(poly.size()));
    const PointD a = poly[k % poly.size()], b = poly[(k + 1) % poly.size()];
    const double t = u(rng);
    double x = a.x + t * (b.x - a.x) + 4 * (2 * u(rng) - 1);
    double y = a.y + t * (b.y - a.y) + 4 * (2 * u(rng) - 1);
    if (u(rng) < outliers) {
      x = 400 * (2 * u(rng) - 1);
      y = 400 * (2 * u(rng) - 1);
    }
    pts.push_back({c * x - s * y + 1000, s * x + c * y + 500});
  }
  return pts;
}

// CPU seconds of this process: the machine is shared, wall time would measure the neighbours.
double seconds(const std::function<void()>& f) {
  timespec a{}, b{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &a);
  f();
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &b);
  return static_cast<double>(b.tv_sec - a.tv_sec) +
         1e-9 * static_cast<double>(b.tv_nsec - a.tv_nsec);
}

struct Row {
  std::string problem, motion, outer, baseline;
  std::size_t n = 0, m = 0;
  double target_s = 0, baseline_s = -1;
  std::string target_result, baseline_result;
};

Row make_row(const char* problem, const char* motion, OuterOffset outer, const char* baseline,
             std::size_t n, std::size_t m) {
  Row r;
  r.problem = problem;
  r.motion = motion;
  r.outer = to_string(outer);
  r.baseline = baseline;
  r.n = n;
  r.m = m;
  return r;
}

void print(const Row& r, bool json) {
  if (json) {
    std::printf(
        "{\"problem\":\"%s\",\"motion\":\"%s\",\"outer\":\"%s\",\"n\":%zu,\"m\":%zu,\"target_"
        "seconds\":%.6f,"
        "\"target_result\":\"%s\",\"baseline\":\"%s\",\"baseline_seconds\":%s,"
        "\"baseline_result\":\"%s\"}\n",
        r.problem.c_str(), r.motion.c_str(), r.outer.c_str(), r.n, r.m, r.target_s,
        r.target_result.c_str(), r.baseline.c_str(),
        r.baseline_s < 0 ? "null" : std::to_string(r.baseline_s).c_str(),
        r.baseline_result.c_str());
  } else {
    char base[32] = "skipped";
    char speed[32] = "-";
    if (r.baseline_s >= 0) {
      std::snprintf(base, sizeof base, "%.4f", r.baseline_s);
      std::snprintf(speed, sizeof speed, "%.1fx", r.baseline_s / r.target_s);
    }
    std::printf("%-11s %-10s %-10s %5zu %3zu %9.4f %-24s %9s %-20s %8s  %s\n", r.problem.c_str(),
                r.motion.c_str(), r.outer.c_str(), r.n, r.m, r.target_s, r.target_result.c_str(),
                base, r.baseline_result.c_str(), speed, r.baseline.c_str());
  }
  std::fflush(stdout);
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

std::string width(const MinWidthResult& r) {
  std::string s = "delta=" + fmt(r.delta_upper);
  if (r.delta_upper - r.delta_lower > 1e-6 * (1.0 + r.delta_upper)) {
    s += " gap " + fmt(r.delta_upper - r.delta_lower);
  }
  return s;
}

std::string cover(const MaxCoverResult& r) {
  return "k=" + std::to_string(r.covered.size()) + "/ub " + std::to_string(r.upper_bound);
}

std::vector<PointD> rotated(const std::vector<PointD>& pts, double a) {
  std::vector<PointD> rp;
  rp.reserve(pts.size());
  for (const PointD& q : pts) {
    rp.push_back({std::cos(a) * q.x + std::sin(a) * q.y, -std::sin(a) * q.x + std::cos(a) * q.y});
  }
  return rp;
}

// Baseline min width: bisection on "max-cover without buckets covers everything".
double naive_min_width(const TemplatePolygon& tp, OuterOffset outer, const std::vector<PointD>& pts,
                       double hi) {
  double lo = 0;
  while (hi - lo > 1e-8 * 300) {
    const double mid = 0.5 * (lo + hi);
    const bool all =
        max_cover_translation(tp, outer, mid, pts, {false}).covered.size() == pts.size();
    (all ? hi : lo) = mid;
  }
  return hi;
}

} // namespace

int main(int argc, char** argv) {
  bool json = false;
  bool quick = false;
  bool field_only = false; // only the bucketing rows (cover-field)
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--json") == 0) json = true;
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    if (std::strcmp(argv[i], "--field-only") == 0) field_only = true;
  }
  if (!json) {
    std::printf("%-11s %-10s %-10s %5s %3s %9s %-24s %9s %-20s %8s  %s\n", "problem", "motion",
                "outer", "n", "m", "target_s", "target_result", "base_s", "base_result", "speedup",
                "baseline");
  }
  const std::vector<std::size_t> ns =
      quick ? std::vector<std::size_t>{100} : std::vector<std::size_t>{100, 1000};
  for (std::size_t n : field_only ? std::vector<std::size_t>{} : ns) {
    for (std::size_t m : {4U, 8U, 16U, 32U, 64U}) {
      const TemplatePolygon tp = make_convex_template(make_template(m));
      // Min width: every point counts, so no outliers. Max cover: 10% outliers, delta = 3.
      const auto pts = make_points(tp.vertices(), n, static_cast<unsigned>(n * 100 + m), 0.0);
      const auto noisy = make_points(tp.vertices(), n, static_cast<unsigned>(n * 100 + m), 0.1);
      const double nm = static_cast<double>(n * m);
      const double n3m2 =
          static_cast<double>(n) * static_cast<double>(n * n) * static_cast<double>(m * m);
      for (const OuterOffset outer : {OuterOffset::kRound, OuterOffset::kLinearized}) {
        const bool round = outer == OuterOffset::kRound;
        {
          Row r = make_row("min-width", "transl", outer, "bisection+plain sweep", n, m);
          MinWidthResult res;
          r.target_s = seconds([&] { res = min_width_translation(tp, outer, pts); });
          r.target_result = width(res);
          if (n * n * m * m <= std::size_t{100} * 100 * 16 * 16) {
            double b = 0;
            r.baseline_s =
                seconds([&] { b = naive_min_width(tp, outer, pts, res.delta_upper * 2); });
            r.baseline_result = "delta=" + fmt(b);
          }
          print(r, json);
        }
        // Max cover under translation, delta = 3 (the noise is +-4: partial cover).
        {
          Row r = make_row("max-cover", "transl", outer, "sweep without buckets", n, m);
          MaxCoverResult res;
          r.target_s = seconds([&] { res = max_cover_translation(tp, outer, 3.0, noisy, {true}); });
          r.target_result = cover(res);
          if (n * n * m * m <= std::size_t{1000} * 1000 * 4 * 4) {
            MaxCoverResult b;
            r.baseline_s =
                seconds([&] { b = max_cover_translation(tp, outer, 3.0, noisy, {false}); });
            r.baseline_result = "k=" + std::to_string(b.covered.size());
          }
          print(r, json);
        }
        // Minimum width with rotation: diagrams (linearized) or cells (round).
        {
          Row r = make_row("min-width", "transl+rot", outer,
                           round ? "angle B&B + translation" : "1-degree sampling", n, m);
          MinWidthResult res;
          r.target_s = seconds([&] { res = min_width_rotation(tp, outer, pts); });
          r.target_result = width(res);
          if (round && nm <= 1000 * 4) {
            RotationOptions o;
            o.method = RotationMethod::kAngleSearch;
            MinWidthResult b;
            r.baseline_s = seconds([&] { b = min_width_rotation(tp, outer, pts, {}, o); });
            r.baseline_result = width(b);
          } else if (!round && nm <= 100 * 16) {
            double best = INFINITY;
            r.baseline_s = seconds([&] {
              MinWidthOptions o;
              o.relative_tolerance = 1e-6;
              for (int k = 0; k < 360; ++k) {
                const auto rp = rotated(pts, 2 * std::numbers::pi * k / 360);
                best = std::min(best, min_width_translation(tp, outer, rp, o).delta_upper);
              }
            });
            r.baseline_result = "delta=" + fmt(best);
          }
          print(r, json);
        }
        // Max cover with rotation: cells, beside the exact diagram sweep (linearized) or the
        // angle branch and bound with translation sweeps (round) where they finish in seconds.
        {
          Row r = make_row("max-cover", "transl+rot", outer,
                           round ? "angle B&B+sweeps, 60 solves" : "rotation diagram", n, m);
          RotationOptions cells;
          cells.method = RotationMethod::kCellSearch;
          MaxCoverResult res;
          r.target_s = seconds([&] { res = max_cover_rotation(tp, outer, 3.0, noisy, cells); });
          r.target_result = cover(res);
          if ((round && nm <= 100 * 4) || (!round && n3m2 <= 100.0 * 100 * 100 * 8 * 8)) {
            RotationOptions o;
            o.method = round ? RotationMethod::kAngleSearch : RotationMethod::kDiagram;
            o.max_evaluations = 60; // the sweeps cost ~0.02 s each at n = 100, m = 4
            MaxCoverResult b;
            r.baseline_s = seconds([&] { b = max_cover_rotation(tp, outer, 3.0, noisy, o); });
            r.baseline_result = cover(b);
          }
          print(r, json);
        }
      }
    }
  }
  // Bucketing pays when the points spread far beyond one template: five noisy copies of the
  // shape scattered over a 4,000 x 4,000 field (Section 3.2).
  for (std::size_t m : {8U, 32U}) {
    const TemplatePolygon tp = make_convex_template(make_template(m));
    std::vector<PointD> field;
    for (int copy = 0; copy < 5; ++copy) {
      for (const PointD& q : make_points(
               tp.vertices(), 200, static_cast<unsigned>(7 * copy + static_cast<int>(m)), 0.1)) {
        field.push_back({q.x + 800.0 * copy - 1500.0, q.y + 650.0 * ((copy * 3) % 5) - 1300.0});
      }
    }
    Row r = make_row("max-cover", "transl", OuterOffset::kRound, "sweep without buckets",
                     field.size(), m);
    r.problem = "cover-field";
    MaxCoverResult res;
    r.target_s =
        seconds([&] { res = max_cover_translation(tp, OuterOffset::kRound, 3.0, field, {true}); });
    r.target_result =
        "k=" + std::to_string(res.covered.size()) + "/ub " + std::to_string(res.upper_bound);
    MaxCoverResult b;
    r.baseline_s =
        seconds([&] { b = max_cover_translation(tp, OuterOffset::kRound, 3.0, field, {false}); });
    r.baseline_result = "k=" + std::to_string(b.covered.size());
    print(r, json);
  }
  return 0;
}
