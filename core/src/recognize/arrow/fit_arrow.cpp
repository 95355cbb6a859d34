// Arrow fitting: the shaft from the two farthest points of the drawing (or, when a barb reaches
// farther from the tail than the tip, to the farthest point away from that barb), a barb on each
// side of the shaft at the head, then a minimax polish of every vertex (and of a curved shaft's
// bulge, or a bent shaft's bends).
#include "recognize/arrow/fit_arrow.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "recognize/arrow/arrow_limits.hpp"
#include "recognize/arrow/shaft_runs.hpp"
#include "recognize/classify/classifier.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
std::vector<PointD> cloud_of(const UnionStroke& u) {
  double total = 0.0;
  for (const auto& p : u.pieces) total += path_length(p);
  std::vector<PointD> out;
  for (const auto& p : u.pieces) {
    const double share = total > 0 ? path_length(p) / total : 1.0;
    const auto n = static_cast<std::size_t>(
        std::max(4.0, std::round(share * static_cast<double>(kCloudPoints))));
    const std::vector<PointD> r = resample(p, n);
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

namespace {

// The barb ends at `head` for a shaft from `other` to `head`: on each side, the point farthest
// from the shaft's line among those that leave the shaft at 10..90 degrees and by more than
// epsilon / 2. Farthest from the line rather than from the head: a bowed shaft's middle can lie
// farther from the head than a short barb's end, but a barb always leaves the line farther.
// Only points within `reach` of the head count (negative: 0.8 times the shaft from `other`).
std::optional<std::pair<PointD, PointD>> find_barbs(const std::vector<PointD>& cloud, PointD head,
                                                    PointD other, double epsilon,
                                                    double reach = -1.0) {
  const PointD back = other - head;
  const double shaft = norm(back);
  if (reach < 0) reach = kMaxBarbFraction * shaft;
  std::optional<PointD> side[2];
  double far[2] = {0.0, 0.0};
  for (const PointD& x : cloud) {
    const PointD d = x - head;
    const double r = norm(d);
    if (r > reach || r <= 0.0) continue;
    const double off = cross(back, d) / shaft;
    if (std::abs(off) < epsilon / 2.0) continue;
    const double a = angle_between(back, d);
    if (a < kMinHeadAngle || a > std::numbers::pi / 2) continue;
    const int k = off > 0 ? 0 : 1;
    if (std::abs(off) > far[k]) {
      far[k] = std::abs(off);
      side[k] = x;
    }
  }
  if (!side[0] || !side[1]) return std::nullopt;
  return std::pair{*side[0], *side[1]};
}

// The polished unknowns: the vertices, the shaft's bulge, a bent shaft's bends and the end of a
// shaft that stops short of the tip.
struct ArrowState {
  std::vector<PointD> v;
  double bulge = 0.0;
  std::vector<PointD> bends;
  std::optional<PointD> shaft_end;
};

// Where along the union a vertex was last found near it: the next search starts there, since
// the polish moves vertices by small steps.
struct PieceHint {
  std::size_t piece = 0;
  std::size_t segment = 0;
};

// Whether p lies farther than `floor` from every piece, and if so how far (else `floor`): a
// vertex nearer the union than the cloud's worst point cannot raise the objective. The segments
// are scanned from `hint` on (the answer does not depend on the order).
double union_distance_above(const UnionStroke& u, PointD p, double floor, PieceHint& hint) {
  const double floor2 = floor * floor;
  double best2 = INFINITY;
  const std::size_t n = u.pieces.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t pi = (hint.piece + k) % n;
    const std::vector<PointD>& piece = u.pieces[pi];
    if (piece.size() == 1) best2 = std::min(best2, dot(p - piece[0], p - piece[0]));
    const std::size_t segments = piece.empty() ? 0 : piece.size() - 1;
    const std::size_t from = k == 0 && hint.segment < segments ? hint.segment : 0;
    for (std::size_t j = 0; j < segments; ++j) {
      const std::size_t i = (from + j) % segments;
      best2 = std::min(best2, segment_distance2(p, piece[i], piece[i + 1]));
      if (best2 <= floor2) {
        hint = {pi, i};
        return floor;
      }
    }
  }
  return std::sqrt(best2);
}

// The fit error of a state: the farthest cloud point from the arrow, or a vertex's distance
// to the union when larger. Evaluation stops once the value reaches `limit` (the compass
// search only asks whether a trial beats its best), starting from the point that was worst
// last time, so that losing trials are rejected after a few points.
struct Objective {
  const std::vector<PointD>& cloud;
  const UnionStroke& u;
  ShapeClass shape;
  mutable std::size_t worst_at = 0;
  mutable PieceHint hints[6 + kMaxShaftBends + 1] = {};
  mutable PieceHint shaft_hints[3 * (kMaxShaftBends + 1)] = {};
  // Per cloud point, the path segment found nearest last time: tried first, since a trial moves
  // one vertex a little.
  mutable std::vector<std::size_t> nearest = std::vector<std::size_t>(cloud.size(), 0);

  // The squared distance from cloud point i to the path, or any value <= floor2 when it is not
  // above floor2 (such a point cannot raise the maximum): the scan stops at the first segment
  // within floor2, starting from the point's last nearest segment.
  // `jump`: the step of the path that joins two pieces (no segment; none: past the end).
  double distance2_above(std::size_t i, const std::vector<PointD>& path, double floor2,
                         std::size_t jump) const {
    const std::size_t segments = path.size() - 1;
    const std::size_t from = nearest[i] < segments ? nearest[i] : 0;
    double d2 = INFINITY;
    for (std::size_t s = 0; s < segments; ++s) {
      const std::size_t j = (from + s) % segments;
      if (j == jump) continue;
      // The path retraces each barb (tip, barb, tip): the way back is the same segment.
      if (j > 0 && path[j + 1] == path[j - 1]) continue;
      const double dj = segment_distance2(cloud[i], path[j], path[j + 1]);
      if (dj < d2) {
        d2 = dj;
        nearest[i] = j;
        if (d2 <= floor2) break;
      }
    }
    return d2;
  }

  double operator()(const ArrowState& a, double limit = INFINITY) const {
    if (std::abs(a.bulge) > kMaxBulge * distance(a.v[0], a.v[1])) return INFINITY;
    const std::vector<PointD> path = arrow_path(shape, a.v, a.bulge, a.bends, a.shaft_end);
    const std::vector<std::size_t> jumps = arrow_jumps(a.bends, a.shaft_end);
    const std::size_t jump = jumps.empty() ? path.size() : jumps.front();
    const double limit2 = limit * limit;
    double worst2 = 0.0;
    for (std::size_t k = 0; k < cloud.size(); ++k) {
      const std::size_t i = (worst_at + k) % cloud.size();
      const double d2 = distance2_above(i, path, worst2, jump);
      if (d2 > worst2) {
        worst2 = d2;
        if (worst2 >= limit2) {
          worst_at = i;
          return std::max(std::sqrt(worst2), limit);
        }
      }
    }
    double worst = std::sqrt(worst2);
    for (std::size_t k = 0; k < a.v.size(); ++k) {
      worst = std::max(worst, union_distance_above(u, a.v[k], worst, hints[k % 6]));
      if (worst >= limit) return worst;
    }
    for (std::size_t k = 0; k < a.bends.size() && k < kMaxShaftBends; ++k) {
      worst = std::max(worst, union_distance_above(u, a.bends[k], worst, hints[6 + k]));
      if (worst >= limit) return worst;
    }
    if (a.shaft_end) {
      worst =
          std::max(worst, union_distance_above(u, *a.shaft_end, worst, hints[6 + kMaxShaftBends]));
      if (worst >= limit) return worst;
    }
    // A curved shaft may bow away from the ink between its ends, which the cloud alone does not
    // see (the certificate does): its quarter points must lie near the union too (a few points:
    // the polish only needs to be steered, the certificate checks the whole shaft).
    if (a.bulge != 0.0) {
      const std::vector<PointD> shaft = shaft_path(a.v[0], a.v[1], a.bulge);
      for (std::size_t k = 0; k < 3; ++k) {
        const PointD q = shaft[(k + 1) * (shaft.size() - 1) / 4];
        worst = std::max(worst, union_distance_above(u, q, worst, shaft_hints[k]));
        if (worst >= limit) return worst;
      }
    }
    // So may a bent shaft's pieces (a piece can cut across a curve of the ink): their quarter
    // points too.
    if (!a.bends.empty()) {
      const std::vector<PointD> shaft =
          shaft_path(a.v[0], a.shaft_end.value_or(a.v[1]), 0.0, a.bends);
      for (std::size_t j = 0; j + 1 < shaft.size() && j <= kMaxShaftBends; ++j) {
        for (std::size_t k = 1; k <= 3; ++k) {
          const PointD q = shaft[j] + (0.25 * static_cast<double>(k)) * (shaft[j + 1] - shaft[j]);
          worst = std::max(worst, union_distance_above(u, q, worst, shaft_hints[3 * j + k - 1]));
          if (worst >= limit) return worst;
        }
      }
    }
    return worst;
  }
};

// The point unknown i of a state: a vertex, then a bend, then the shaft's end; null for the
// bulge (the last unknown).
PointD* unknown_point(ArrowState& a, std::size_t i) {
  if (i < a.v.size()) return &a.v[i];
  if (i < a.v.size() + a.bends.size()) return &a.bends[i - a.v.size()];
  if (a.shaft_end && i == a.v.size() + a.bends.size()) return &*a.shaft_end;
  return nullptr;
}

// Compass search on every coordinate of the vertices and bends and on the bulge (as
// refine_minimax does for one stroke).
double polish(ArrowState& a, const Objective& objective, double step, bool curved) {
  double best = objective(a);
  const double min_step = step / 32.0;
  // A gain within rounding is none (kLeastRefineGain, as refine_minimax): the first step is
  // epsilon / 2, and epsilon is at most an eighth of the size, so 16 steps are at most the size.
  const double least_gain = kLeastRefineGain * 16.0 * step;
  const std::size_t points = a.v.size() + a.bends.size() + (a.shaft_end ? 1 : 0);
  std::size_t budget = 60 * (points + 1);
  const std::size_t unknowns = points + (curved ? 1 : 0);
  while (step >= min_step && budget > 0) {
    bool improved = false;
    for (std::size_t i = 0; i < unknowns && budget > 0 && !improved; ++i) {
      PointD* point = unknown_point(a, i);
      for (const PointD dir : {PointD{1, 0}, PointD{-1, 0}, PointD{0, 1}, PointD{0, -1}}) {
        if (point == nullptr && dir.y != 0) continue; // the bulge is one number
        // The trial is made in place and undone from saved values (no copy per trial).
        const double old_bulge = a.bulge;
        const PointD old_point = point != nullptr ? *point : PointD{};
        if (point == nullptr) {
          a.bulge += step * dir.x;
        } else {
          *point = *point + step * dir;
        }
        const double value = objective(a, best - least_gain);
        --budget;
        if (value < best - least_gain) {
          best = value;
          improved = true;
          break;
        }
        a.bulge = old_bulge;
        if (point != nullptr) *point = old_point;
      }
    }
    if (!improved) step /= 2.0;
  }
  return best;
}

// A seed polished: none when it lies farther than kSeedWithin epsilons from the drawing (every
// vertex of a seed lies on the ink, so a drawing that is such an arrow fits it within a few
// epsilons already: the polish moves vertices by about epsilon, anything else is not worth
// polishing). A compass search stalls where two errors tie (a bend between its pieces): started
// again from where it stopped, with its full step, it often goes on (while it may still certify).
std::optional<double> polish_seed(ArrowState& a, const Objective& objective, double epsilon,
                                  bool curved) {
  if (objective(a) > kSeedWithin * epsilon) return std::nullopt;
  double error = polish(a, objective, epsilon / 2.0, curved);
  for (int again = 0;
       again < 2 && error > kSecondStartAbove * epsilon && error <= kRepolishBelow * epsilon;
       ++again) {
    error = polish(a, objective, epsilon / 2.0, curved);
  }
  return error;
}

// The bulge of the arc through the shaft's ends that follows the points drawn along the shaft
// (those nearer the shaft than either barb, away from its ends): a parabola's mean offset from
// its chord is 2/3 of its sagitta.
double estimate_bulge(const std::vector<PointD>& cloud, const ArrowState& a) {
  const double c = distance(a.v[0], a.v[1]);
  if (c <= 0) return 0.0;
  const PointD u = (1.0 / c) * (a.v[1] - a.v[0]);
  double sum = 0;
  std::size_t n = 0;
  for (const PointD& p : cloud) {
    const double t = dot(p - a.v[0], u);
    const double d = segment_distance(p, a.v[0], a.v[1]);
    if (t < 0.1 * c || t > 0.9 * c || d > 0.25 * c) continue;
    if (d > segment_distance(p, a.v[1], a.v[2]) || d > segment_distance(p, a.v[1], a.v[3])) {
      continue;
    }
    sum += cross(u, p - a.v[0]);
    ++n;
  }
  if (n == 0) return 0.0;
  return std::clamp(1.5 * sum / static_cast<double>(n), -kMaxBulge * c, kMaxBulge * c);
}

// Least-squares refinement of a single arrow's start (a few rounds of k-lines): every point
// goes to its nearest piece (shaft, barb 1, barb 2), each piece's line is refitted, the tip
// becomes the point nearest the three lines, and the ends the farthest projections. Also
// estimates the shaft's bulge (a parabola's mean offset is 2/3 of its sagitta).
void settle(const std::vector<PointD>& cloud, ArrowState& a) {
  for (int round = 0; round < 3; ++round) {
    std::vector<PointD> group[3];
    for (const PointD& p : cloud) {
      const double d[3] = {segment_distance(p, a.v[0], a.v[1]), segment_distance(p, a.v[1], a.v[2]),
                           segment_distance(p, a.v[1], a.v[3])};
      group[std::min_element(d, d + 3) - d].push_back(p);
    }
    if (group[0].size() < 3 || group[1].size() < 2 || group[2].size() < 2) return;
    Line line[3];
    for (int k = 0; k < 3; ++k) line[k] = fit_line(group[k]);
    // The point nearest the three lines: sum over k of (I - d d^T) (x - p_k) = 0.
    double m00 = 0, m01 = 0, m11 = 0, r0 = 0, r1 = 0;
    for (const Line& l : line) {
      const PointD d = l.direction;
      const double a00 = 1 - d.x * d.x, a01 = -d.x * d.y, a11 = 1 - d.y * d.y;
      m00 += a00, m01 += a01, m11 += a11;
      r0 += a00 * l.point.x + a01 * l.point.y;
      r1 += a01 * l.point.x + a11 * l.point.y;
    }
    const double det = m00 * m11 - m01 * m01;
    if (std::abs(det) < 1e-12) return;
    const PointD tip{(r0 * m11 - r1 * m01) / det, (m00 * r1 - m01 * r0) / det};
    auto far_end = [&](int k) {
      PointD best = a.v[static_cast<std::size_t>(k == 0 ? 0 : k + 1)];
      double far = -1;
      for (const PointD& p : group[k]) {
        if (distance(p, tip) > far) far = distance(p, tip), best = p;
      }
      const PointD d = line[k].direction;
      return line[k].point + dot(best - line[k].point, d) * d;
    };
    a.v = {far_end(0), tip, far_end(1), far_end(2)};
  }
  a.bulge = estimate_bulge(cloud, a);
}

Fit make_fit(ShapeClass shape, ArrowState a, double error) {
  Fit f;
  f.shape = shape;
  f.clean.kind = CleanShape::Kind::kPolyline;
  f.clean.path = arrow_path(shape, a.v, a.bulge, a.bends, a.shaft_end);
  f.clean.jumps = arrow_jumps(a.bends, a.shaft_end);
  const std::vector<PointD>& v = a.v;
  const PointD shaft = v[1] - v[0];
  f.params.center = 0.5 * (v[0] + v[1]);
  f.params.rotation = std::atan2(shaft.y, shaft.x);
  const PointD back = shaft_back(v[0], v[1], a.bulge, a.bends);
  f.params.head_angle = 0.5 * (angle_between(back, v[2] - v[1]) + angle_between(back, v[3] - v[1]));
  f.params.shaft_bulge = a.bulge;
  f.params.shaft_bends = std::move(a.bends);
  f.params.shaft_end = a.shaft_end;
  f.params.vertices = std::move(a.v);
  f.fit_error = error;
  return f;
}

// How far a straight shaft strays from the union at its quarter points: the straight arrow's
// objective measures the cloud's distance to the arrow, not the shaft's to the ink (a straight
// shaft cuts across a bent one's corner).
double shaft_stray(const UnionStroke& u, const ArrowState& a) {
  double worst = 0.0;
  PieceHint hint;
  for (const double f : {0.25, 0.5, 0.75}) {
    worst = std::max(worst, union_distance_above(u, a.v[0] + f * (a.v[1] - a.v[0]), worst, hint));
  }
  return worst;
}

// A new bend for the shaft of `a` (the Douglas-Peucker rule): among the points drawn along the
// shaft (nearer it than every barb), the one farthest from it when farther than epsilon / 2,
// inserted between the ends of the shaft piece it is nearest to. False when none stands out.
bool add_bend(const std::vector<PointD>& cloud, ArrowState& a, double epsilon) {
  const std::vector<PointD> shaft = shaft_path(a.v[0], a.v[1], 0.0, a.bends);
  double far = epsilon / 2.0;
  std::optional<std::pair<PointD, std::size_t>> best;
  for (const PointD& p : cloud) {
    double barb = INFINITY;
    for (std::size_t k = 2; k < a.v.size(); ++k) {
      barb = std::min(barb, segment_distance(p, a.v[k < 4 ? 1 : 0], a.v[k]));
    }
    std::size_t piece = 0;
    double d = INFINITY;
    for (std::size_t j = 0; j + 1 < shaft.size(); ++j) {
      const double dj = segment_distance(p, shaft[j], shaft[j + 1]);
      if (dj < d) d = dj, piece = j;
    }
    if (d > barb || d <= far) continue;
    far = d;
    best = std::pair{p, piece};
  }
  if (!best) return false;
  a.bends.insert(a.bends.begin() + static_cast<std::ptrdiff_t>(best->second), best->first);
  return true;
}

// The barbs found again against a bent shaft's end pieces: found against the chord, a head's
// "barb" may be the shaft's own last piece (its bend leaves the chord's line farther than a barb
// does). The reach stays 0.8 chords, as the plausibility rule measures barbs.
void refind_barbs(const std::vector<PointD>& cloud, ArrowState& a, double epsilon) {
  const std::vector<PointD> shaft = shaft_path(a.v[0], a.v[1], 0.0, a.bends);
  const double reach = kMaxBarbFraction * distance(a.v[0], a.v[1]);
  if (const auto h = find_barbs(cloud, a.v[1], shaft[shaft.size() - 2], epsilon, reach)) {
    a.v[2] = h->first;
    a.v[3] = h->second;
  }
  if (a.v.size() < 6) return;
  if (const auto t = find_barbs(cloud, a.v[0], shaft[1], epsilon, reach)) {
    a.v[4] = t->first;
    a.v[5] = t->second;
  }
}

// Bent shafts from the straight arrow `a` (the raw start: its tail and tip are ends of the
// drawing, not pulled towards a bend by a straight polish): one bend, then a second while the
// fit is still loose, each polished with all the vertices.
void fit_bent(const std::vector<PointD>& cloud, const Objective& objective, ArrowState a,
              double epsilon, double rank_to_beat, std::vector<Fit>& out) {
  const double base =
      objective.shape == ShapeClass::kDoubleArrow ? kDoubleParameters : kStraightParameters;
  a.bulge = 0.0;
  double error = INFINITY;
  // A second bend only for a one-bend fit that is loose but near (kRepolishBelow): a bend more
  // rarely rescues a drawing one bend does not come near.
  for (std::size_t k = 1; k <= kMaxShaftBends && error > kSecondStartAbove * epsilon &&
                          (k == 1 || error <= kRepolishBelow * epsilon);
       ++k) {
    const double parameters = base + kBendParameters * static_cast<double>(k);
    if (kPricePerParameter * parameters >= rank_to_beat || !add_bend(cloud, a, epsilon)) return;
    refind_barbs(cloud, a, epsilon);
    const std::optional<double> polished = polish_seed(a, objective, epsilon, false);
    if (!polished) return;
    error = *polished;
    out.push_back(make_fit(objective.shape, a, error));
  }
}

// The arrows from one start (tail, tip, barb ends): straight, curved when the straight one fits
// too loosely, and bent when neither fits tightly (only straight ones for kStraightShafts).
void fit_from_start(const std::vector<PointD>& cloud, const UnionStroke& u, const ArrowState& start,
                    double epsilon, double rank_to_beat, ArrowSearch search,
                    std::vector<Fit>& out) {
  const bool any_shaft = search == ArrowSearch::kAll;
  const bool try_curved = any_shaft && kPricePerParameter * kCurvedParameters < rank_to_beat;
  const double step = epsilon / 2.0;
  const Objective objective{cloud, u, ShapeClass::kArrow};
  // Straight: polished from the raw start or the least-squares start, the one fitting better
  // first; the other only when the first does not fit tightly enough to pass surely.
  ArrowState settled = start;
  settle(cloud, settled);
  ArrowState curved = settled;
  settled.bulge = 0.0;
  ArrowState first = start, second = std::move(settled);
  if (objective(second) < objective(first)) std::swap(first, second);
  double e_straight = polish(first, objective, step, false);
  if (e_straight > kSecondStartAbove * epsilon) {
    const double e_second = polish(second, objective, step, false);
    if (e_second < e_straight) {
      e_straight = e_second;
      first = std::move(second);
    }
  }
  out.push_back(make_fit(ShapeClass::kArrow, first, e_straight));
  // Curved, when the shaft bows visibly and the straight arrow fits too loosely to pass:
  // polished from the straight arrow bent to follow its shaft's points, and from the
  // least-squares start.
  // The straight arrow's error both ways: its objective misses a shaft that cuts a corner.
  double e_best = std::max(e_straight, shaft_stray(u, first));
  if (e_straight > kStraightFraction * epsilon && try_curved) {
    ArrowState bowed = first;
    bowed.bulge = estimate_bulge(cloud, bowed);
    for (ArrowState* c : {&bowed, &curved}) {
      if (std::abs(c->bulge) < epsilon / 4.0) continue;
      const double e = polish(*c, objective, step, true);
      e_best = std::min(e_best, e);
      out.push_back(make_fit(ShapeClass::kArrow, std::move(*c), e));
    }
  }
  // Bent (a polyline shaft), when neither the straight nor the curved shaft fits tightly enough
  // to pass surely.
  if (any_shaft && e_best > kSecondStartAbove * epsilon)
    fit_bent(cloud, objective, start, epsilon, rank_to_beat, out);
}

// The start of an arrow whose shaft is drawn along `s.run`, its head found against the shaft's
// end among the points off the run; none when no head stands out or a barb does not end within
// epsilon of one of `ends` (a barb is drawn to its end: a stroke ends or turns back there; the
// farthest point of a curve drawn near the shaft's end is no barb).
std::optional<ArrowState> head_at_shaft_end(const std::vector<PointD>& cloud, const ShaftRun& s,
                                            double epsilon, const std::vector<PointD>& ends) {
  std::vector<PointD> off_run;
  for (const PointD& p : cloud) {
    if (polyline_distance(p, s.run) > epsilon / 2.0) off_run.push_back(p);
  }
  const PointD tip = s.tip;
  const auto head =
      find_barbs(off_run, tip, s.back_point, epsilon, kMaxBarbFraction * path_length(s.run));
  auto drawn_to = [&](PointD b) {
    return std::any_of(ends.begin(), ends.end(),
                       [&](PointD e) { return distance(b, e) <= epsilon; });
  };
  if (!head || !drawn_to(head->first) || !drawn_to(head->second)) return std::nullopt;
  return ArrowState{{s.run.front(), tip, head->first, head->second}, 0.0, {}, std::nullopt};
}

// The curved and bent arrows from a start found against its shaft's end, the shaft seeded from
// the run drawn along it (its middle's offset, its Douglas-Peucker bends), each polished.
void fit_shaft_end_start(const std::vector<PointD>& cloud, const UnionStroke& u,
                         const ArrowState& start, const std::vector<PointD>& run, double epsilon,
                         double rank_to_beat, std::vector<Fit>& out) {
  const Objective objective{cloud, u, ShapeClass::kArrow};
  auto polished = [&](ArrowState a, bool curved) {
    if (const auto e = polish_seed(a, objective, epsilon, curved)) {
      out.push_back(make_fit(ShapeClass::kArrow, std::move(a), *e));
    }
  };
  // A bulge beyond the limit is started at the limit (the polish keeps within it).
  const double limit = kMaxBulge * distance(start.v[0], start.v[1]);
  const double bulge = std::clamp(run_bulge(run), -0.99 * limit, 0.99 * limit);
  if (kPricePerParameter * kCurvedParameters < rank_to_beat && std::abs(bulge) >= epsilon / 4.0) {
    ArrowState curved = start;
    curved.bulge = bulge;
    polished(std::move(curved), true);
  }
  std::vector<PointD> bends = run_bends(run, epsilon);
  const double parameters =
      kStraightParameters + kBendParameters * static_cast<double>(bends.size());
  if (bends.empty() || kPricePerParameter * parameters >= rank_to_beat) return;
  ArrowState bent = start;
  bent.bends = std::move(bends);
  polished(std::move(bent), false);
}

// The single arrows from `tail` to `tip` with the barbs found at the tip against the chord (none
// when no barb stands out on both sides). Returns the best fit error among them (infinite when
// no head is found).
double fit_single(const std::vector<PointD>& cloud, const UnionStroke& u, PointD tail, PointD tip,
                  double epsilon, double rank_to_beat, ArrowSearch search, std::vector<Fit>& out) {
  const auto head = find_barbs(cloud, tip, tail, epsilon);
  if (!head) return INFINITY;
  const std::size_t before = out.size();
  const ArrowState start{{tail, tip, head->first, head->second}, 0.0, {}, std::nullopt};
  fit_from_start(cloud, u, start, epsilon, rank_to_beat, search, out);
  double best = INFINITY;
  for (std::size_t i = before; i < out.size(); ++i) best = std::min(best, out[i].fit_error);
  return best;
}

// Arrows whose head is found against a curved or bent shaft's own end (shaft_runs.hpp), at every
// place the drawing may have its tip.
void fit_heads_at_shaft_end(const std::vector<PointD>& cloud, const UnionStroke& u, double epsilon,
                            double rank_to_beat, std::vector<Fit>& out) {
  const std::vector<std::pair<double, PointD>> turns = turn_places(u, epsilon);
  std::vector<PointD> ends;
  ends.reserve(turns.size());
  for (const auto& place : turns) ends.push_back(place.second);
  const std::vector<PointD> tips = tip_candidates(turns, epsilon);
  // An arrow ends or turns back at its tail, its tip and its barbs' ends (twice that for a double
  // arrow, a few more where a stroke goes back over its tip): a drawing that does so in more
  // places is writing or a scribble, not worth the search.
  if (tips.size() > kMaxArrowPlaces) return;
  for (const PointD& tip : tips) {
    for (const ShaftRun& s : shaft_runs(u, tip, epsilon)) {
      if (const auto start = head_at_shaft_end(cloud, s, epsilon, ends)) {
        std::vector<PointD> shaft = s.run; // tail to tip
        shaft.back() = s.tip;
        fit_shaft_end_start(cloud, u, *start, shaft, epsilon, rank_to_beat, out);
      }
    }
  }
}

// Another tip for a shaft from `tail`: the point farthest from the tail that lies more than
// 2 epsilon from `tip` (the first guess). A barb that leans forward can end farther from the
// tail than the tip does; the tip is then the farthest point away from that barb's end.
std::optional<PointD> other_tip(const std::vector<PointD>& cloud, PointD tail, PointD tip,
                                double epsilon) {
  std::optional<PointD> best;
  double far = 0.0;
  for (const PointD& p : cloud) {
    if (distance(p, tip) <= 2.0 * epsilon) continue;
    if (distance(p, tail) > far) far = distance(p, tail), best = p;
  }
  // A tip much nearer the tail than the first guess would make barbs longer than the shaft.
  if (!best || far < 0.5 * distance(tail, tip)) return std::nullopt;
  return best;
}

// The head stroke's tip: its point farthest from its chord, when that stands out by more than
// epsilon (a head turns at its tip, as piece_role asks of a head drawn alone).
std::optional<PointD> head_tip(const std::vector<PointD>& head, double epsilon) {
  std::optional<PointD> tip;
  double far = epsilon;
  for (const PointD& p : head) {
    const double d = segment_distance(p, head.front(), head.back());
    if (d > far) far = d, tip = p;
  }
  return tip;
}

// Arrows whose head is one stroke and shaft another, in either order: seeded from the strokes
// themselves (tip at the head's turn, barbs at its ends, tail at the shaft's end away from the
// tip), then polished. The farthest points of such a drawing need not be its tail and tip: a
// long barb can reach farther than the shaft, and the shaft may stop short of the tip.
void fit_from_strokes(const std::vector<PointD>& cloud, const UnionStroke& u, double epsilon,
                      std::vector<Fit>& out) {
  if (!arrow_rules().seed_from_strokes || u.pieces.size() != 2) return;
  const Objective objective{cloud, u, ShapeClass::kArrow};
  for (std::size_t h = 0; h < 2; ++h) {
    const std::vector<PointD>& head = u.pieces[h];
    const std::vector<PointD>& shaft = u.pieces[1 - h];
    const std::optional<PointD> tip = head_tip(head, epsilon);
    if (!tip) continue;
    const PointD tail =
        distance(shaft.front(), *tip) > distance(shaft.back(), *tip) ? shaft.front() : shaft.back();
    const ArrowState start{{tail, *tip, head.front(), head.back()}, 0.0, {}, std::nullopt};
    ArrowState a = start;
    const double e = polish(a, objective, epsilon / 2.0, false);
    out.push_back(make_fit(ShapeClass::kArrow, std::move(a), e));
    // The shaft may stop short of the tip: its end seeded from the shaft stroke's end nearest
    // the tip (arrow_implausibility asks that it be aimed at the tip and the gap be short).
    if (!arrow_rules().gapped_shafts) continue;
    ArrowState gapped = start;
    gapped.shaft_end = tail == shaft.front() ? shaft.back() : shaft.front();
    const double e_gapped = polish(gapped, objective, epsilon / 2.0, false);
    out.push_back(make_fit(ShapeClass::kArrow, std::move(gapped), e_gapped));
  }
}

} // namespace

ArrowRules& arrow_rules() {
  static ArrowRules rules;
  return rules;
}

std::vector<Fit> fit_arrows(const UnionStroke& u, double epsilon, double rank_to_beat,
                            ArrowSearch search) {
  auto may_win = [&](double parameters) { return kPricePerParameter * parameters < rank_to_beat; };
  if (!may_win(kStraightParameters)) return {};
  const std::vector<PointD> cloud = cloud_of(u);
  if (cloud.size() < 8) return {};
  // The two farthest points: the tail and the tip (barbs lean back, so the tip is the farthest
  // point from the tail).
  std::size_t a = 0, b = 0;
  double diameter = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (std::size_t j = i + 1; j < cloud.size(); ++j) {
      const double d = distance(cloud[i], cloud[j]);
      if (d > diameter) {
        diameter = d;
        a = i;
        b = j;
      }
    }
  }
  if (diameter <= 2.0 * epsilon) return {};
  std::vector<Fit> out;
  double best = INFINITY;
  for (const bool tip_is_b : {true, false}) {
    const PointD tail = tip_is_b ? cloud[a] : cloud[b], tip = tip_is_b ? cloud[b] : cloud[a];
    best = std::min(best, fit_single(cloud, u, tail, tip, epsilon, rank_to_beat, search, out));
  }
  // Neither end of the diameter is the tip when a barb reaches farther from the tail than the
  // tip: then no head stands out at either end, and each end is tried as the tail with the
  // other tip.
  if (!std::isfinite(best)) {
    for (const bool tail_is_a : {true, false}) {
      const PointD tail = tail_is_a ? cloud[a] : cloud[b], tip = tail_is_a ? cloud[b] : cloud[a];
      if (const auto t = other_tip(cloud, tail, tip, epsilon)) {
        fit_single(cloud, u, tail, *t, epsilon, rank_to_beat, search, out);
      }
    }
  }
  fit_from_strokes(cloud, u, epsilon, out);
  if (arrow_rules().heads_at_shaft_end && search == ArrowSearch::kAll) {
    fit_heads_at_shaft_end(cloud, u, epsilon, rank_to_beat, out);
  }
  const auto at_a = find_barbs(cloud, cloud[a], cloud[b], epsilon);
  const auto at_b = find_barbs(cloud, cloud[b], cloud[a], epsilon);
  if (at_a && at_b && may_win(kDoubleParameters)) {
    const ArrowState start{
        {cloud[a], cloud[b], at_b->first, at_b->second, at_a->first, at_a->second},
        0.0,
        {},
        std::nullopt};
    ArrowState st = start;
    const Objective objective{cloud, u, ShapeClass::kDoubleArrow};
    const double e = polish(st, objective, epsilon / 2.0, false);
    const double both_ways = std::max(e, shaft_stray(u, st));
    out.push_back(make_fit(ShapeClass::kDoubleArrow, std::move(st), e));
    if (search == ArrowSearch::kAll && both_ways > kSecondStartAbove * epsilon) {
      fit_bent(cloud, objective, start, epsilon, rank_to_beat, out);
    }
  }
  return out;
}

} // namespace penshape::recognize_detail
