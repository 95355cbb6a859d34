#include "no_certificate.hpp"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "certified.hpp"
#include "grid_frame.hpp"

namespace penshape::fast {
namespace {

IPt round_point(DPt p) { return {std::llround(p.x), std::llround(p.y)}; }

// An axis-parallel square cell [c - half, c + half]²; centres and halves are exact doubles.
struct Cell {
  DPt c;
  double half;
};

// half · sqrt(2), rounded up: the cell's radius around its centre (the double nearest sqrt(2),
// 1.4142135623730951, lies above it: its square exceeds 2 exactly). An interval product: CGAL
// keeps its operands and result behind an opaque barrier, so the multiplication cannot move out
// of the upward-rounding scope (a plain product could, and would then round to nearest).
double cell_radius(double half) {
  const UpwardRounding rounding;
  return (detail::IntervalNT(half) * detail::IntervalNT(1.4142135623730951)).sup();
}

// x + d when that sum is exact in double (Fast2Sum: the rounding error of x + d is recovered
// exactly when |d| <= |x|), so that the four children tile their parent exactly.
bool exact_sum(double x, double d, double& out) {
  out = x + d;
  return std::fabs(d) <= std::fabs(x) ? (out - x) == d : (out - d) == x;
}

// The smallest double with at most 8 significant bits that is >= v (> 0): quadtree halves
// then stay short dyadic numbers, so child centres are exact for many levels.
double short_dyadic_at_least(double v) {
  int e = 0;
  std::frexp(v, &e); // v in [2^(e-1), 2^e)
  const double unit = std::ldexp(1.0, e - 8);
  return std::ceil(v / unit) * unit; // division by a power of two and ceil: exact
}

class NoWitnessCheck {
 public:
  NoWitnessCheck(const NoCheckInput& in, const CancelHook& cancel) : in_(in), cancel_(cancel) {}

  bool run(IPt q) {
    // q ∈ Q: inside Q̃ and farther than η0 from its boundary (H(Q, Q̃) <= η0).
    if (in_.q->winding(q) <= 0) return false;
    if (!all_edges_farther(*in_.q, at_point(q), kInputRounding)) return false;
    // disk >= r + eps.
    return covers(q, add_up(in_.radius.hi, in_.tolerance.hi));
  }

  // Every point of D_disk(q) lies in a cell that is dropped for missing the disk or that has a
  // witness.
  bool covers(IPt q, double disk) {
    std::vector<Cell> stack{{to_d(q), short_dyadic_at_least(disk)}};
    std::size_t visited = 0;
    while (!stack.empty()) {
      const Cell cell = stack.back();
      stack.pop_back();
      if (++visited > in_.max_cells) return false;
      if ((visited & 255U) == 0 && cancel_ && cancel_()) throw Cancelled();
      const double rho = cell_radius(cell.half);
      // |c - q| > disk + rho: no point of the cell is in the disk.
      if (compare_point_distance(at_point(cell.c), at_point(q), add_up(disk, rho)) > 0) continue;
      if (has_witness(cell.c, rho)) continue;
      if (rho <= in_.min_cell) return false;
      const double h = cell.half / 2.0;
      for (const double dx : {-h, h}) {
        for (const double dy : {-h, h}) {
          Cell child{{0.0, 0.0}, h};
          if (!exact_sum(cell.c.x, dx, child.c.x) || !exact_sum(cell.c.y, dy, child.c.y)) {
            return false;
          }
          stack.push_back(child);
        }
      }
    }
    return true;
  }

 private:
  // A grid point z with |z - c| + rho <= r and d(z, Q) > eps: then z ∈ D_r(y) \ offset(Q, eps)
  // for every y of the cell, so no y of the cell lies in Π.
  bool has_witness(DPt c, double rho) const {
    const double reach = sub_down(in_.radius.lo, rho); // reach + rho <= r
    if (reach <= 0.0) return false;
    if (good(round_point(c), c, reach)) return true;
    // Proposal: the nearest point of the outer offset's boundary, pushed outwards (region on
    // the left), computed in double; good() decides.
    constexpr auto kNone = static_cast<std::uint32_t>(-1);
    std::uint32_t id = kNone;
    (void)in_.outer_offset->grid().nearest_closer_than(c, reach, id);
    if (id != kNone) {
      const Segment& g = in_.outer_offset->segments()[id];
      const DPt a = g.da(), b = g.db();
      const double dx = b.x - a.x, dy = b.y - a.y;
      const double t = detail::proposed_foot_parameter(c, a, b);
      const double len = std::sqrt(dx * dx + dy * dy);
      const DPt z{a.x + t * dx + in_.push * dy / len, a.y + t * dy - in_.push * dx / len};
      if (good(round_point(z), c, reach)) return true;
    }
    return good(round_point(away_from_q(c)), c, reach);
  }

  // Proposal near Q̃ itself (a sliver thinner than a grid unit, which the offsets were computed
  // without): c moved straight away from the nearest edge of Q̃ until it clears eps + η0.
  DPt away_from_q(DPt c) const {
    const double clear = in_.tolerance.hi + kInputRounding + in_.push;
    constexpr auto kNone = static_cast<std::uint32_t>(-1);
    std::uint32_t id = kNone;
    (void)in_.q->grid().nearest_closer_than(c, clear, id);
    if (id == kNone) return c;
    const Segment& g = in_.q->segments()[id];
    const DPt a = g.da(), b = g.db();
    const double t = detail::proposed_foot_parameter(c, a, b);
    const DPt foot{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    DPt dir{c.x - foot.x, c.y - foot.y};
    if (dir.x == 0.0 && dir.y == 0.0) dir = {b.y - a.y, a.x - b.x}; // on the edge: its normal
    const double len = std::hypot(dir.x, dir.y);
    if (!(len > 0.0)) return c;
    return {foot.x + dir.x / len * clear, foot.y + dir.y / len * clear};
  }

  bool good(IPt z, DPt c, double reach) const {
    if (compare_point_distance(at_point(z), at_point(c), reach) > 0) return false;
    // Outside Q̃ and d(z, ∂Q̃) > eps + η0, so d(z, Q) >= d(z, Q̃) - η0 > eps.
    if (in_.q->winding(z) > 0) return false;
    return all_edges_farther(*in_.q, at_point(z), add_up(in_.tolerance.hi, kInputRounding));
  }

  const NoCheckInput& in_;
  const CancelHook& cancel_;
};

} // namespace

bool verify_no_vertex_witness(const NoCheckInput& in, IPt rounded, const CancelHook& cancel) {
  // D_{r+eps}(v) ⊆ D_{r+eps+η0}(ṽ), as |v - ṽ| <= η0.
  NoWitnessCheck check(in, cancel);
  return check.covers(rounded, add_up(add_up(in.radius.hi, in.tolerance.hi), kInputRounding));
}

bool verify_no_witness(const NoCheckInput& in, IPt q, const CancelHook& cancel) {
  NoWitnessCheck check(in, cancel);
  return check.run(q);
}

} // namespace penshape::fast
