// Chaining strokes into one path, and the gap between two strokes.
#include "recognize/group/stroke_chain.hpp"

#include <algorithm>
#include <numeric>

#include "geometry/exact_predicates.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

PointD start_of(const std::vector<PointD>& p, bool reversed) {
  return reversed ? p.back() : p.front();
}
PointD end_of(const std::vector<PointD>& p, bool reversed) {
  return reversed ? p.front() : p.back();
}

struct Order {
  std::vector<std::size_t> index;
  std::vector<bool> reversed;
};

// Best directions for a fixed order: a shortest path over (piece, direction) states.
double best_directions(const std::vector<std::vector<PointD>>& pieces, Order& order) {
  const std::size_t n = order.index.size();
  std::vector<double> cost[2] = {std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  std::vector<int> from[2] = {std::vector<int>(n, 0), std::vector<int>(n, 0)};
  for (std::size_t k = 1; k < n; ++k) {
    for (int d = 0; d < 2; ++d) {
      const PointD s = start_of(pieces[order.index[k]], d == 1);
      double best = INFINITY;
      for (int e = 0; e < 2; ++e) {
        const double c = cost[e][k - 1] + distance(end_of(pieces[order.index[k - 1]], e == 1), s);
        if (c < best) {
          best = c;
          from[d][k] = e;
        }
      }
      cost[d][k] = best;
    }
  }
  int d = cost[0][n - 1] <= cost[1][n - 1] ? 0 : 1;
  const double total = cost[d][n - 1];
  order.reversed.assign(n, false);
  for (std::size_t k = n; k-- > 0;) {
    order.reversed[k] = d == 1;
    d = from[d][k];
  }
  return total;
}

Order greedy_order(const std::vector<std::vector<PointD>>& pieces) {
  Order o;
  std::vector<bool> used(pieces.size(), false);
  o.index.push_back(0);
  o.reversed.push_back(false);
  used[0] = true;
  for (std::size_t k = 1; k < pieces.size(); ++k) {
    const PointD end = end_of(pieces[o.index.back()], o.reversed.back());
    double best = INFINITY;
    std::size_t pick = 0;
    bool rev = false;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (used[i]) continue;
      for (const bool r : {false, true}) {
        const double d = distance(end, start_of(pieces[i], r));
        if (d < best) {
          best = d;
          pick = i;
          rev = r;
        }
      }
    }
    used[pick] = true;
    o.index.push_back(pick);
    o.reversed.push_back(rev);
  }
  return o;
}

// The order and directions of chain_pieces() (pieces must not be empty).
Order best_order(const std::vector<std::vector<PointD>>& pieces) {
  if (pieces.size() > kExhaustiveUpTo) return greedy_order(pieces);
  Order best;
  Order o;
  o.index.resize(pieces.size());
  std::iota(o.index.begin(), o.index.end(), std::size_t{0});
  double best_cost = INFINITY;
  do {
    const double c = best_directions(pieces, o);
    if (c < best_cost) {
      best_cost = c;
      best = o;
    }
  } while (std::next_permutation(o.index.begin(), o.index.end()));
  return best;
}

} // namespace

std::vector<double> chain_jumps(const std::vector<std::vector<PointD>>& pieces) {
  std::vector<double> out;
  if (pieces.empty()) return out;
  const Order o = best_order(pieces);
  for (std::size_t k = 1; k < o.index.size(); ++k) {
    out.push_back(distance(end_of(pieces[o.index[k - 1]], o.reversed[k - 1]),
                           start_of(pieces[o.index[k]], o.reversed[k])));
  }
  return out;
}

std::vector<PointD> chain_pieces(const std::vector<std::vector<PointD>>& pieces) {
  if (pieces.empty()) return {};
  const Order best = best_order(pieces);
  std::vector<PointD> out;
  for (std::size_t k = 0; k < best.index.size(); ++k) {
    const std::vector<PointD>& p = pieces[best.index[k]];
    const auto before = out.size();
    out.insert(out.end(), p.begin(), p.end());
    if (best.reversed[k])
      std::reverse(out.begin() + static_cast<std::ptrdiff_t>(before), out.end());
  }
  // Consecutive duplicates (a piece starting where the previous ended) would be zero-length.
  out.erase(std::unique(out.begin(), out.end(),
                        [](PointD a, PointD b) { return a.x == b.x && a.y == b.y; }),
            out.end());
  return out;
}

double polyline_gap(const std::vector<PointD>& a, const std::vector<PointD>& b) {
  // Two segments that do not cross are nearest at an end of one of them.
  double best = INFINITY;
  for (const PointD& p : a) best = std::min(best, polyline_distance(p, b));
  for (const PointD& p : b) best = std::min(best, polyline_distance(p, a));
  if (best == 0.0) return 0.0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    for (std::size_t j = 0; j + 1 < b.size(); ++j) {
      if (detail::segments_cross_properly(a[i], a[i + 1], b[j], b[j + 1])) return 0.0;
    }
  }
  return best;
}

} // namespace penshape::recognize_detail
