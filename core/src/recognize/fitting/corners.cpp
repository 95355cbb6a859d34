// Corner search by dynamic programming over chord costs computed in O(1) from prefix sums, and
// total-least-squares lines.
#include <cmath>
#include <limits>

#include "recognize/fitting/fit.hpp"

namespace penshape::recognize_detail {
namespace {

// Prefix moments of a (possibly doubled) point sequence, centred for accuracy.
class ChordCost {
 public:
  explicit ChordCost(const std::vector<PointD>& pts) : pts_(pts) {
    const std::size_t n = pts.size();
    for (const PointD& p : pts) c_ = c_ + p;
    c_ = (1.0 / static_cast<double>(n)) * c_;
    sx_.assign(n + 1, 0.0);
    sy_ = sxx_ = syy_ = sxy_ = sx_;
    for (std::size_t i = 0; i < n; ++i) {
      const PointD q = pts[i] - c_;
      sx_[i + 1] = sx_[i] + q.x;
      sy_[i + 1] = sy_[i] + q.y;
      sxx_[i + 1] = sxx_[i] + q.x * q.x;
      syy_[i + 1] = syy_[i] + q.y * q.y;
      sxy_[i + 1] = sxy_[i] + q.x * q.y;
    }
  }
  // Sum of squared distances of points i..j (inclusive) to the line through points i and j.
  [[nodiscard]] double operator()(std::size_t i, std::size_t j) const {
    const PointD a = pts_[i] - c_;
    const PointD d = pts_[j] - pts_[i];
    const double len = norm(d);
    if (len <= 0.0) return 0.0;
    const double nx = -d.y / len;
    const double ny = d.x / len;
    const double c = nx * a.x + ny * a.y;
    const double cnt = static_cast<double>(j - i + 1);
    const double sx = sx_[j + 1] - sx_[i], sy = sy_[j + 1] - sy_[i];
    const double sxx = sxx_[j + 1] - sxx_[i], syy = syy_[j + 1] - syy_[i];
    const double sxy = sxy_[j + 1] - sxy_[i];
    const double v = nx * nx * sxx + 2 * nx * ny * sxy + ny * ny * syy -
                     2 * c * (nx * sx + ny * sy) + c * c * cnt;
    return std::max(v, 0.0);
  }

 private:
  const std::vector<PointD>& pts_;
  PointD c_;
  std::vector<double> sx_, sy_, sxx_, syy_, sxy_;
};

// ChordCost's values remembered: the closed search runs the chain search from several starts
// over the same doubled cycle, and each start would otherwise recompute most chords. A value is
// computed once, by the same call, so every chain sees the same costs bit for bit.
class RememberedCost {
 public:
  // For chords (i, j) with i < rows and j - i <= span.
  RememberedCost(const ChordCost& cost, std::size_t rows, std::size_t span)
      : cost_(cost), span_(span + 1), table_(rows * span_, kUnknown) {}
  [[nodiscard]] double operator()(std::size_t i, std::size_t j) {
    double& v = table_[i * span_ + (j - i)];
    if (v == kUnknown) v = cost_(i, j);
    return v;
  }

 private:
  static constexpr double kUnknown = -1.0; // costs are >= 0 (or NaN, never -1)
  const ChordCost& cost_;
  std::size_t span_;
  std::vector<double> table_;
};

// Best paths first -> last over pts[first..last] through 2..most vertices (first and last
// included), one dynamic programme for every count: the best path through k vertices takes the
// best ways of reaching each point as the (k-1)-th vertex, which no other count changes.
class ChainSearch {
 public:
  template <typename Cost>
  ChainSearch(Cost&& chord_cost, std::size_t first, std::size_t last, std::size_t most)
      : first_(first),
        n_(last - first + 1),
        dp_(most, std::vector<double>(n_, kInf)),
        from_(most, std::vector<std::size_t>(n_, 0)) {
    // dp_[j][v]: best cost reaching local index v as the j-th vertex (0-based, v = 0 is first).
    dp_[0][0] = 0.0;
    for (std::size_t j = 1; j < most; ++j) {
      for (std::size_t v = j; v < n_; ++v) {
        if (j + 1 == most && v != n_ - 1) continue; // the last count only ends at `last`
        for (std::size_t u = j - 1; u < v; ++u) {
          if (dp_[j - 1][u] == kInf) continue;
          const double c = dp_[j - 1][u] + chord_cost(first + u, first + v);
          if (c < dp_[j][v]) {
            dp_[j][v] = c;
            from_[j][v] = u;
          }
        }
      }
    }
  }
  // The cost of the best path through k vertices (2 <= k <= most), and the path.
  [[nodiscard]] double cost(std::size_t k) const { return dp_[k - 1][n_ - 1]; }
  [[nodiscard]] std::vector<std::size_t> chain(std::size_t k) const {
    std::vector<std::size_t> out(k, 0);
    std::size_t v = n_ - 1;
    for (std::size_t j = k; j-- > 0;) {
      out[j] = first_ + v;
      v = from_[j][v];
    }
    return out;
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  std::size_t first_, n_;
  std::vector<std::vector<double>> dp_;
  std::vector<std::vector<std::size_t>> from_;
};

} // namespace

std::vector<std::size_t> open_corners(const std::vector<PointD>& pts, std::size_t k) {
  if (k < 2 || pts.size() < k) return {};
  return ChainSearch(ChordCost(pts), 0, pts.size() - 1, k).chain(k);
}

std::vector<std::vector<std::size_t>> closed_corner_chains(const std::vector<PointD>& pts,
                                                           std::size_t most) {
  const std::size_t n = pts.size();
  std::vector<std::vector<std::size_t>> chains(most + 1);
  if (most < 3 || n < 6) return chains;
  // The cycle, doubled so that a chain may start anywhere.
  std::vector<PointD> twice = pts;
  twice.insert(twice.end(), pts.begin(), pts.end());
  const ChordCost chords(twice);
  RememberedCost cost(chords, 2 * n, n); // chords within one turn of the doubled cycle
  // Start candidates: the points turning the most over a short window, and the point farthest
  // from the centroid (a vertex of any polygon the stroke resembles).
  std::vector<std::pair<double, std::size_t>> turning;
  PointD c;
  for (const PointD& p : pts) c = c + p;
  c = (1.0 / static_cast<double>(n)) * c;
  std::size_t far = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const PointD a = pts[(i + n - 3) % n];
    const PointD b = pts[(i + 3) % n];
    const PointD u = pts[i] - a;
    const PointD v = b - pts[i];
    turning.emplace_back(-std::abs(std::atan2(cross(u, v), dot(u, v))), i);
    if (distance(pts[i], c) > distance(pts[far], c)) far = i;
  }
  std::sort(turning.begin(), turning.end());
  std::vector<std::size_t> starts{far};
  for (std::size_t i = 0; i < turning.size() && starts.size() < 5; ++i) {
    if (std::find(starts.begin(), starts.end(), turning[i].second) == starts.end()) {
      starts.push_back(turning[i].second);
    }
  }
  // k corners need 2k fit points; the search runs to the largest count the points allow.
  const std::size_t top = std::min(most, n / 2);
  std::vector<double> best(top + 1, std::numeric_limits<double>::infinity());
  for (const std::size_t s : starts) {
    // k + 1 vertices: the start appears again at the end of the cycle.
    const ChainSearch search(cost, s, s + n, top + 1);
    for (std::size_t k = 3; k <= top; ++k) {
      if (!(search.cost(k + 1) < best[k])) continue;
      best[k] = search.cost(k + 1);
      std::vector<std::size_t> chain = search.chain(k + 1);
      chain.pop_back();
      for (std::size_t& v : chain) v %= n;
      chains[k] = std::move(chain);
    }
  }
  return chains;
}

const std::vector<std::size_t>& closed_corners(const PreparedStroke& s, std::size_t k) {
  if (s.closed_corner_chains.size() <= k) {
    s.closed_corner_chains = closed_corner_chains(s.fit_points, std::max(k, kMaxPolygonCorners));
  }
  return s.closed_corner_chains[k];
}

Line fit_line(std::span<const PointD> pts) {
  PointD c;
  for (const PointD& p : pts) c = c + p;
  c = (1.0 / static_cast<double>(pts.size())) * c;
  double sxx = 0, syy = 0, sxy = 0;
  for (const PointD& p : pts) {
    const PointD q = p - c;
    sxx += q.x * q.x;
    syy += q.y * q.y;
    sxy += q.x * q.y;
  }
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  return {c, {std::cos(angle), std::sin(angle)}};
}

} // namespace penshape::recognize_detail
