// Corner seeds where a closed stroke turns sharply (fit.hpp, sharp_turn_corners): the corners a
// hand drew, where the least-squares corner search (corners.cpp) may settle on a side's lumps.
#include <algorithm>
#include <cmath>
#include <optional>

#include "recognize/fitting/fit.hpp"
#include "recognize/fitting/path_turn.hpp"

namespace penshape::recognize_detail {
namespace {

// Turns are read between chords this share of the stroke's length either way (a quarter of an
// octagon's side): a corner turns whole within it, a circle by about 22 degrees.
constexpr double kTurnWindow = 1.0 / 32.0;
constexpr std::size_t kTurnSamples = 256;
// Turns that are corners: at least twice the stroke's median turn (a circle turns about as much
// everywhere, a polygon's sides hardly), so round strokes cost no fit.
constexpr double kLeastTurnOverMedian = 2.0;

using Turn = PreparedStroke::PathTurn;

// The stroke's turns every 1/256 of its length, sharpest first (stable: ties in arc order).
const std::vector<Turn>& turns_by_sharpness(const PreparedStroke& s, const ArcLengthPath& path) {
  if (s.turns_by_sharpness) return *s.turns_by_sharpness;
  const double w = kTurnWindow * path.length(), step = path.length() / kTurnSamples;
  std::vector<Turn> turns;
  for (double at = w; w > 0.0 && at <= path.length() - w; at += step) {
    turns.push_back({at, path.turn_at(at, w).value_or(0.0)});
  }
  std::stable_sort(turns.begin(), turns.end(),
                   [](const Turn& a, const Turn& b) { return a.turn > b.turn; });
  return s.turns_by_sharpness.emplace(std::move(turns));
}

// The sharpest turns first, each at least two windows from those taken along the stroke and in
// the plane (one corner, once: a closed stroke that runs on past its start turns at that corner
// twice), until k are taken or the next turns less than `least_turn`.
std::vector<Turn> sharpest_apart(const ArcLengthPath& path, const std::vector<Turn>& turns,
                                 std::size_t k, double window, double least_turn) {
  std::vector<Turn> taken;
  for (const Turn& t : turns) {
    if (taken.size() == k || t.turn < least_turn) break;
    const PointD p = path.point_at(t.at);
    const bool apart = std::all_of(taken.begin(), taken.end(), [&](const Turn& o) {
      return std::abs(o.at - t.at) >= 2.0 * window &&
             distance(path.point_at(o.at), p) >= 2.0 * window;
    });
    if (apart) taken.push_back(t);
  }
  return taken;
}

} // namespace

std::size_t sharp_turn_count(const PreparedStroke& s, std::size_t at_most, double least_turn) {
  const ArcLengthPath path(s.points);
  return sharpest_apart(path, turns_by_sharpness(s, path), at_most, kTurnWindow * path.length(),
                        least_turn)
      .size();
}

std::vector<PointD> sharp_turn_corners(const PreparedStroke& s, std::size_t k, double least_turn) {
  const ArcLengthPath path(s.points);
  const double w = kTurnWindow * path.length();
  const std::vector<Turn>& turns = turns_by_sharpness(s, path);
  if (turns.empty()) return {};
  std::vector<Turn> taken = sharpest_apart(path, turns, k, w, 0.0);
  if (taken.size() != k) return {};
  const double median = turns[turns.size() / 2].turn;
  const double least = taken.back().turn; // taken sharpest first
  if (least < least_turn || least < kLeastTurnOverMedian * median) return {};
  std::sort(taken.begin(), taken.end(), [](const Turn& a, const Turn& b) { return a.at < b.at; });
  std::vector<PointD> out;
  out.reserve(k);
  for (const Turn& t : taken) out.push_back(path.point_at(t.at));
  return out;
}

} // namespace penshape::recognize_detail
