// The verifier's quadtree proofs. A cell is a square with rational corner and side; its centre c
// and ρ = side · 99/140 (>= the half-diagonal side/√2, since (99/140)² > 1/2) bound every point
// x of the cell by |x - c| <= ρ, and distances to a set are 1-Lipschitz, so a test at c with ρ
// subtracted or added settles the whole cell. Cells that no test settles split in four.
#include "verify/verify_cover.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <numbers>
#include <vector>

namespace penshape::verify {
namespace {

enum class Verdict { kSettled, kSplit, kRefuted };

struct Cell {
  ExactPoint corner;
  Rational side;
  int depth = 0;
};

const Rational kHalfDiagonal(99, 140);

// Breadth first finds a counterexample at the coarsest level that shows it (a depth-first walk
// could spend the budget along a tight curve first); depth first keeps a failing proof short.
enum class Order { kBreadthFirst, kDepthFirst };

template <typename Rule>
CoverOutcome cover(const ExactPoint& corner, const Rational& side, const VerifyLimits& limits,
                   Order order, Rule&& rule) {
  CoverOutcome out;
  std::deque<Cell> stack{{corner, side, 0}};
  while (!stack.empty()) {
    Cell cell;
    if (order == Order::kDepthFirst) {
      cell = std::move(stack.back());
      stack.pop_back();
    } else {
      cell = std::move(stack.front());
      stack.pop_front();
    }
    ++out.cells;
    const Rational half = cell.side / 2;
    const VPoint c = vpoint({cell.corner.x + half, cell.corner.y + half});
    const Rational rho = cell.side * kHalfDiagonal;
    const Verdict v = rule(cell, c, rho);
    if (v == Verdict::kSettled) continue;
    if (v == Verdict::kRefuted || cell.depth >= limits.max_depth || out.cells >= limits.max_cells) {
      out.status = v == Verdict::kRefuted ? VerifyStatus::kRefuted : VerifyStatus::kUnproven;
      out.where = c.e;
      return out;
    }
    for (int i = 0; i < 4; ++i) {
      ExactPoint k = cell.corner;
      if ((i & 1) != 0) k.x += half;
      if ((i & 2) != 0) k.y += half;
      stack.push_back({std::move(k), half, cell.depth + 1});
    }
  }
  return out;
}

// The square around a box [low, high] grown by `grow` on every side.
std::pair<ExactPoint, Rational> square_around(const ExactPoint& low, const ExactPoint& high,
                                              const Rational& grow) {
  const Rational w = high.x - low.x;
  const Rational h = high.y - low.y;
  Rational side = (w > h ? w : h) + 2 * grow;
  if (sgn(side) <= 0) side = 1;
  return {{low.x - grow, low.y - grow}, side};
}

// The cell's corners, enclosed.
std::array<std::pair<Interval, Interval>, 4> corners_of(const Cell& cell) {
  const Interval x0 = enclose(cell.corner.x);
  const Interval y0 = enclose(cell.corner.y);
  const Interval x1 = enclose(cell.corner.x + cell.side);
  const Interval y1 = enclose(cell.corner.y + cell.side);
  return {{{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}}};
}

// A superset [t0, t1] of the parameters t ∈ [0, 1] with a + t·(b - a) in the box
// [lo_x, hi_x] × [lo_y, hi_y]; empty (t0 > t1) only when the segment surely misses the box.
std::pair<double, double> clip_parameters(const VPoint& a, const VPoint& b, const Interval& lo_x,
                                          const Interval& hi_x, const Interval& lo_y,
                                          const Interval& hi_y) {
  double t0 = 0.0, t1 = 1.0;
  auto axis = [&](const Interval& from, const Interval& to, const Interval& lo,
                  const Interval& hi) {
    const Interval d = to - from;
    if (d.inf() > 0) {
      t0 = std::max(t0, ((lo - from) / d).inf());
      t1 = std::min(t1, ((hi - from) / d).sup());
    } else if (d.sup() < 0) {
      t0 = std::max(t0, ((hi - from) / d).inf());
      t1 = std::min(t1, ((lo - from) / d).sup());
    }
  };
  axis(a.x, b.x, lo_x, hi_x);
  axis(a.y, b.y, lo_y, hi_y);
  return {t0, t1};
}

// cross(b - a, p - a) <= t·|b - a|, exactly (t may be negative): sign p's side of the line ab
// scaled by its distance, against t.
bool exact_side_at_most(const ExactPoint& a, const ExactPoint& b, const ExactPoint& p,
                        const Rational& t) {
  const Rational ux = b.x - a.x, uy = b.y - a.y;
  const Rational cr = ux * (p.y - a.y) - uy * (p.x - a.x);
  const Rational len2 = ux * ux + uy * uy;
  if (sgn(t) >= 0) return sgn(cr) <= 0 || cr * cr <= t * t * len2;
  return sgn(cr) < 0 && cr * cr >= t * t * len2;
}

// Every corner of the cell at signed distance <= t from the line ab (exactly).
bool corners_at_most(const Cell& cell, const ExactPoint& a, const ExactPoint& b,
                     const Rational& t) {
  for (int i = 0; i < 4; ++i) {
    const ExactPoint k{cell.corner.x + ((i & 1) != 0 ? cell.side : Rational(0)),
                       cell.corner.y + ((i & 2) != 0 ? cell.side : Rational(0))};
    if (!exact_side_at_most(a, b, k, t)) return false;
  }
  return true;
}

// The flat rule for (A), where offset(P, r) runs along the ε-band of one edge e of Q (the common
// case: P's edges parallel to Q's at depth r - ε, where the Lipschitz rule would need cells as
// small as the margin along the whole edge). With s the signed distance to e's line, the strip
// R_e = {projection on e, |s| <= ε} lies in offset(Q, ε). For c ∉ P and 2ρ <= r, every point x
// of the cell in offset(P, r) is within r of an edge g of P that meets the cell grown by r (x is
// within r of P's boundary: a point of P in the cell makes the cell meet ∂P, and the cell's
// diameter 2ρ <= r), and s over the stadium of g's clipped part is at most its endpoints' s plus
// r. Intervals only: when they cannot decide, the rule declines and the cell splits.
bool flat_band_covers(const Cell& cell, const VPoint& c, const Rational& rho, const EdgeSet& p,
                      const EdgeSet& q, const Rational& r, const Rational& eps) {
  if (2 * rho > r) return false;
  const double cx = c.e.x.get_d(), cy = c.e.y.get_d();
  const double reach = Rational(r + rho).get_d();
  const auto e = q.approx_nearest_edge(cx, cy, 2.0 * reach);
  if (!e) return false;
  const VPoint& ea = *e->first;
  const VPoint& eb = *e->second;
  const Interval ux = eb.x - ea.x, uy = eb.y - ea.y;
  const Interval len2 = ux * ux + uy * uy;
  if (len2.inf() <= 0) return false;
  const Interval len = CGAL::sqrt(len2);
  auto s = [&](const Interval& x, const Interval& y) {
    return (ux * (y - ea.y) - uy * (x - ea.x)) / len;
  };
  const Interval ie = enclose(eps), ir = enclose(r);
  double s_lo = INFINITY, s_hi = -INFINITY;
  for (const auto& [kx, ky] : corners_of(cell)) {
    const Interval dot = (kx - ea.x) * ux + (ky - ea.y) * uy;
    if (dot.inf() < 0 || dot.sup() > len2.inf()) return false; // projects beyond e
    const Interval sk = s(kx, ky);
    s_lo = std::min(s_lo, sk.inf());
    s_hi = std::max(s_hi, sk.sup());
  }
  const Interval grow = enclose(r + cell.side / 2);
  const Interval lo_x = c.x - grow, hi_x = c.x + grow, lo_y = c.y - grow, hi_y = c.y + grow;
  for (const auto& [ga, gb] : p.edges_near(cx, cy, reach)) {
    const auto [t0, t1] = clip_parameters(*ga, *gb, lo_x, hi_x, lo_y, hi_y);
    if (t0 > t1) continue;
    const Interval sa = s(ga->x, ga->y), sb = s(gb->x, gb->y);
    const Interval at0 = sa + Interval(t0) * (sb - sa);
    const Interval at1 = sa + Interval(t1) * (sb - sa);
    const Interval hi = Interval(std::max(at0.sup(), at1.sup())) + ir;
    const Interval lo = Interval(std::min(at0.inf(), at1.inf())) - ir;
    if (std::min(hi.sup(), s_hi) <= ie.inf() && std::max(lo.inf(), s_lo) >= -ie.inf()) continue;
    // Too close for intervals (a certificate tight to the last bit): decide each side exactly,
    // with g's whole endpoints or with the cell's corners.
    const Rational depth = r - eps;
    const bool upper = (exact_side_at_most(ea.e, eb.e, ga->e, -depth) &&
                        exact_side_at_most(ea.e, eb.e, gb->e, -depth)) ||
                       corners_at_most(cell, ea.e, eb.e, eps);
    const bool lower = (exact_side_at_most(eb.e, ea.e, ga->e, -depth) &&
                        exact_side_at_most(eb.e, ea.e, gb->e, -depth)) ||
                       corners_at_most(cell, eb.e, ea.e, eps);
    if (!upper || !lower) return false;
  }
  return true;
}

} // namespace

CoverOutcome prove_offset_within(const EdgeSet& p, const EdgeSet& q, const Rational& r,
                                 const Rational& eps, const VerifyLimits& limits) {
  if (p.empty()) return {};
  const Threshold eps_t = threshold(eps);
  const Threshold r_t = threshold(r);
  auto rule = [&](const Cell& cell, const VPoint& c, const Rational& rho) {
    const bool in_q = q.contains(c);
    // Within rho <= eps of a point of Q, or wholly inside Q.
    if (in_q && rho <= eps) return Verdict::kSettled;
    const Threshold rho_t = threshold(rho);
    if (in_q && q.all_beyond(c, rho_t)) return Verdict::kSettled;
    // Farther than r from P everywhere: the cell misses offset(P, r).
    if (!p.contains(c) && p.all_beyond(c, threshold(r + rho))) return Verdict::kSettled;
    if (rho <= eps && q.any_within(c, threshold(eps - rho))) return Verdict::kSettled;
    if (!p.contains(c) && flat_band_covers(cell, c, rho, p, q, r, eps)) return Verdict::kSettled;
    // c itself in offset(P, r) and beyond eps from Q: a counterexample.
    if (!in_q && q.all_beyond(c, eps_t) && (p.contains(c) || p.any_within(c, r_t))) {
      return Verdict::kRefuted;
    }
    return Verdict::kSplit;
  };
  const auto [corner, side] = square_around(p.low(), p.high(), r);
  return cover(corner, side, limits, Order::kBreadthFirst, rule);
}

CoverOutcome prove_covered(const EdgeSet& q, const EdgeSet& p, const Rational& reach,
                           const VerifyLimits& limits) {
  if (q.empty()) return {};
  const Threshold reach_t = threshold(reach);
  auto rule = [&](const Cell&, const VPoint& c, const Rational& rho) {
    const bool in_q = q.contains(c);
    const Threshold rho_t = threshold(rho);
    if (!in_q && q.all_beyond(c, rho_t)) return Verdict::kSettled; // misses Q
    const bool in_p = p.contains(c);
    if (in_p && rho <= reach) return Verdict::kSettled;
    if (in_p && p.all_beyond(c, rho_t)) return Verdict::kSettled; // inside P
    if (rho <= reach && p.any_within(c, threshold(reach - rho))) return Verdict::kSettled;
    if (in_q && !in_p && p.all_beyond(c, reach_t)) return Verdict::kRefuted;
    return Verdict::kSplit;
  };
  const auto [corner, side] = square_around(q.low(), q.high(), Rational(0));
  return cover(corner, side, limits, Order::kBreadthFirst, rule);
}

namespace {

// An offset (dx, dy) of length below `reach` such that (cx, cy) + (dx, dy) seems farthest from
// Q (doubles; only a proposal, the caller adds it exactly and checks). The farthest point of a
// disk from Q is usually on its circle: sample the circle, then refine the best angle; the centre
// is tried too. Offsets, not points: far from the origin, absolute doubles would round the point
// by more than the room between the circle and r.
std::pair<double, double> propose_far_offset(const EdgeSet& q, double cx, double cy, double reach,
                                             double eps) {
  const double radius = reach * (1.0 - 1e-9);
  auto score = [&](double dx, double dy) {
    const double x = cx + dx, y = cy + dy;
    return q.approx_contains(x, y) ? -1.0 : q.approx_distance(x, y, 4.0 * eps);
  };
  auto at = [&](double a) {
    return std::pair<double, double>{radius * std::cos(a), radius * std::sin(a)};
  };
  std::pair<double, double> best{0.0, 0.0};
  double best_score = score(0.0, 0.0);
  double best_angle = 0.0;
  constexpr int kDirections = 32;
  double step = 2.0 * std::numbers::pi / kDirections;
  for (int k = 0; k < kDirections; ++k) {
    const auto z = at(step * k);
    const double sc = score(z.first, z.second);
    if (sc > best_score) {
      best_score = sc;
      best = z;
      best_angle = step * k;
    }
  }
  for (int round = 0; round < 12; ++round) {
    step /= 2.0;
    for (const double a : {best_angle - step, best_angle + step}) {
      const auto z = at(a);
      const double sc = score(z.first, z.second);
      if (sc > best_score) {
        best_score = sc;
        best = z;
        best_angle = a;
      }
    }
  }
  return best;
}

Rational squared(const Rational& v) { return v * v; }

} // namespace

CoverOutcome prove_unservable(const EdgeSet& q, const ExactPoint& w, const Rational& r,
                              const Rational& eps, const VerifyLimits& limits) {
  const Rational reach = r + eps;
  const Rational reach2 = reach * reach;
  const Rational r2 = r * r;
  const Threshold eps_t = threshold(eps);
  const double eps_d = eps.get_d();
  auto rule = [&](const Cell& cell, const VPoint& c, const Rational& rho) {
    // Cells wholly outside D_{r+eps}(w) need nothing.
    const Rational x1 = cell.corner.x + cell.side;
    const Rational y1 = cell.corner.y + cell.side;
    Rational dx = 0, dy = 0;
    if (w.x < cell.corner.x) dx = cell.corner.x - w.x;
    if (w.x > x1) dx = w.x - x1;
    if (w.y < cell.corner.y) dy = cell.corner.y - w.y;
    if (w.y > y1) dy = w.y - y1;
    if (dx * dx + dy * dy > reach2) return Verdict::kSettled;
    if (rho >= r) return Verdict::kSplit;
    const auto [dx_z, dy_z] =
        propose_far_offset(q, c.e.x.get_d(), c.e.y.get_d(), Rational(r - rho).get_d(), eps_d);
    const VPoint z = vpoint(ExactPoint{c.e.x + exact(dx_z), c.e.y + exact(dy_z)});
    // Every corner (so, by convexity, the cell) strictly within r of z.
    const std::array<ExactPoint, 4> corners{cell.corner, ExactPoint{x1, cell.corner.y},
                                            ExactPoint{cell.corner.x, y1}, ExactPoint{x1, y1}};
    for (const auto& k : corners) {
      if (squared(k.x - z.e.x) + squared(k.y - z.e.y) >= r2) return Verdict::kSplit;
    }
    if (q.contains(z) || !q.all_beyond(z, eps_t)) return Verdict::kSplit;
    return Verdict::kSettled;
  };
  return cover(ExactPoint{w.x - reach, w.y - reach}, 2 * reach, limits, Order::kDepthFirst, rule);
}

} // namespace penshape::verify
