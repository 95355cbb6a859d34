#include "no_certificate.hpp"

#include <cmath>
#include <vector>

#include "grid_frame.hpp"

namespace penshape::fast {
namespace {

constexpr double kParamRounding = 1.0 / 256.0;

IPt round_point(DPt p) { return {std::llround(p.x), std::llround(p.y)}; }

struct Cell {
  DPt c;
  double half; // half side; the cell's radius is half * sqrt(2)
};

class NoWitnessCheck {
 public:
  NoWitnessCheck(const NoCheckInput& in, const CancelHook& cancel) : in_(in), cancel_(cancel) {}

  bool run(IPt q) {
    // q ∈ Q: inside Q̃ and farther than η from its boundary (H(Q, Q̃) <= η).
    if (in_.q->winding(q) <= 0) return false;
    const double clear = kInputRounding + kDistanceSlack;
    if (in_.q->distance(to_d(q), clear + 1.0) <= clear) return false;

    const double disk = in_.radius + in_.tolerance + kParamRounding;
    std::vector<Cell> stack{{to_d(q), disk}};
    std::size_t visited = 0;
    while (!stack.empty()) {
      const Cell cell = stack.back();
      stack.pop_back();
      if (++visited > in_.max_cells) return false;
      if ((visited & 255U) == 0 && cancel_ && cancel_()) throw Cancelled();
      const double rho = cell.half * std::sqrt(2.0) + kDistanceSlack;
      if (std::hypot(cell.c.x - static_cast<double>(q.x), cell.c.y - static_cast<double>(q.y)) -
              rho >
          disk) {
        continue; // misses the disk
      }
      if (has_witness(cell.c, rho)) continue;
      if (cell.half * std::sqrt(2.0) <= in_.min_cell) return false;
      const double h = cell.half / 2.0;
      for (const double dx : {-h, h}) {
        for (const double dy : {-h, h}) stack.push_back({{cell.c.x + dx, cell.c.y + dy}, h});
      }
    }
    return true;
  }

 private:
  // A grid point z with |z - c| + rho < r and d(z, Q) > eps.
  bool has_witness(DPt c, double rho) const {
    const double reach = in_.radius - kParamRounding - kDistanceSlack - rho;
    if (reach <= 0.0) return false;
    if (good(round_point(c), c, reach)) return true;
    // The nearest point of the outer offset's boundary, pushed outwards (region on the left).
    double best = reach;
    const Segment* nearest = nullptr;
    in_.outer_offset->for_each_near(c.x - reach, c.y - reach, c.x + reach, c.y + reach,
                                    [&](std::size_t k) {
                                      const Segment& g = in_.outer_offset->segments()[k];
                                      const double d = point_segment_distance(c, g.da(), g.db());
                                      if (d < best) {
                                        best = d;
                                        nearest = &g;
                                      }
                                    });
    if (nearest == nullptr) return false;
    const DPt a = nearest->da(), b = nearest->db();
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((c.x - a.x) * dx + (c.y - a.y) * dy) / len2 : 0.0;
    t = std::fmin(1.0, std::fmax(0.0, t));
    const double len = std::sqrt(len2);
    const DPt z{a.x + t * dx + in_.push * dy / len, a.y + t * dy - in_.push * dx / len};
    return good(round_point(z), c, reach);
  }

  bool good(IPt z, DPt c, double reach) const {
    if (std::hypot(static_cast<double>(z.x) - c.x, static_cast<double>(z.y) - c.y) > reach) {
      return false;
    }
    if (in_.q->winding(z) > 0) return false;
    // d(z, Q) >= d(z, Q̃) - η > eps.
    const double need = in_.tolerance + kParamRounding + kInputRounding + kDistanceSlack;
    return in_.q->distance(to_d(z), need + 1.0) > need;
  }

  const NoCheckInput& in_;
  const CancelHook& cancel_;
};

} // namespace

bool verify_no_witness(const NoCheckInput& in, IPt q, const CancelHook& cancel) {
  NoWitnessCheck check(in, cancel);
  return check.run(q);
}

} // namespace penshape::fast
