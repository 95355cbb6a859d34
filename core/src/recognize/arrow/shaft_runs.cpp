// The places a drawing may have an arrow's tip, and the runs of its strokes that may be a curved
// or bent shaft reaching it (shaft_runs.hpp).
#include "recognize/arrow/shaft_runs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "recognize/fitting/geometry.hpp"
#include "recognize/fitting/path_turn.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

// The first point of a run at least `reach` from `from` (its end when none is).
PointD point_beyond(const std::vector<PointD>& run, PointD from, double reach) {
  for (const PointD& p : run) {
    if (distance(p, from) >= reach) return p;
  }
  return run.back();
}

// `run` (from near the tip outwards) as a shaft, tail to tip; none when too short or straight.
std::optional<ShaftRun> as_shaft(std::vector<PointD> run, PointD tip, double epsilon) {
  const double length = path_length(run);
  if (run.size() < 3 || distance(run.back(), tip) <= 2.0 * epsilon) return std::nullopt;
  const PointD back_point =
      point_beyond(run, tip, std::min(std::max(epsilon, kShaftEndReach * length), 0.5 * length));
  if (angle_between(back_point - tip, run.back() - tip) < kMinShaftEndTurn) return std::nullopt;
  std::reverse(run.begin(), run.end());
  return ShaftRun{std::move(run), tip, back_point};
}

} // namespace

std::vector<std::pair<double, PointD>> turn_places(const UnionStroke& u, double epsilon) {
  std::vector<std::pair<double, PointD>> turns;
  for (const std::vector<PointD>& piece : u.pieces) {
    if (piece.empty()) continue;
    turns.emplace_back(std::numbers::pi, piece.front());
    turns.emplace_back(std::numbers::pi, piece.back());
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 1; i + 1 < piece.size(); ++i) {
      while (lo + 1 < i && distance(piece[lo + 1], piece[i]) >= epsilon / 2.0) ++lo;
      hi = std::max(hi, i);
      while (hi + 1 < piece.size() && distance(piece[hi], piece[i]) < epsilon / 2.0) ++hi;
      const double turn = angle_between(piece[i] - piece[lo], piece[hi] - piece[i]);
      if (turn > kTipTurn) turns.emplace_back(turn, piece[i]);
    }
  }
  std::stable_sort(turns.begin(), turns.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  return turns;
}

std::vector<PointD> tip_candidates(const std::vector<std::pair<double, PointD>>& turns,
                                   double epsilon) {
  std::vector<PointD> out;
  for (const auto& place : turns) {
    const PointD p = place.second;
    if (std::none_of(out.begin(), out.end(), [&](PointD q) { return distance(p, q) <= epsilon; })) {
      out.push_back(p);
    }
  }
  return out;
}

std::vector<ShaftRun> shaft_runs(const UnionStroke& u, PointD tip, double epsilon) {
  std::vector<ShaftRun> out;
  for (const std::vector<PointD>& piece : u.pieces) {
    std::size_t at = 0;
    double near = INFINITY;
    for (std::size_t i = 0; i < piece.size(); ++i) {
      if (distance(piece[i], tip) < near) near = distance(piece[i], tip), at = i;
    }
    if (near > epsilon) continue;
    for (const bool backwards : {true, false}) {
      std::vector<PointD> run; // from the tip outwards
      if (backwards) {
        run.assign(piece.rbegin() + static_cast<std::ptrdiff_t>(piece.size() - 1 - at),
                   piece.rend());
      } else {
        run.assign(piece.begin() + static_cast<std::ptrdiff_t>(at), piece.end());
      }
      std::size_t last_near = 0;
      for (std::size_t i = 0; i < run.size(); ++i) {
        if (distance(run[i], tip) <= epsilon) last_near = i;
      }
      if (last_near > 0) {
        std::vector<PointD> rest(run.begin() + static_cast<std::ptrdiff_t>(last_near), run.end());
        if (auto s = as_shaft(std::move(rest), tip, epsilon)) out.push_back(std::move(*s));
      }
      if (auto s = as_shaft(std::move(run), tip, epsilon)) out.push_back(std::move(*s));
    }
  }
  return out;
}

std::vector<PointD> run_bends(const std::vector<PointD>& run, double epsilon) {
  auto farthest = [&](std::size_t a, std::size_t b) {
    std::pair<std::size_t, double> best{a, epsilon / 2.0};
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = segment_distance(run[i], run[a], run[b]);
      if (d > best.second) best = {i, d};
    }
    return best;
  };
  if (run.size() < 3) return {};
  const std::size_t last = run.size() - 1;
  const std::size_t first = farthest(0, last).first;
  if (first == 0) return {};
  const auto left = farthest(0, first), right = farthest(first, last);
  if (left.first == 0 && right.first == first) return {run[first]};
  if (left.second >= right.second) return {run[left.first], run[first]};
  return {run[first], run[right.first]};
}

double run_bulge(const std::vector<PointD>& run) {
  const double half = 0.5 * path_length(run);
  double along = 0.0;
  PointD mid = run.back();
  for (std::size_t i = 1; i < run.size(); ++i) {
    along += distance(run[i - 1], run[i]);
    if (along >= half) {
      mid = run[i];
      break;
    }
  }
  const double chord = distance(run.front(), run.back());
  return chord > 0.0 ? cross(run.back() - run.front(), mid - run.front()) / chord : 0.0;
}

} // namespace penshape::recognize_detail
