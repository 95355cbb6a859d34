// Max-cover under translation and rotation by branch and bound over (tx, ty, theta) cells
// (rotation.hpp, method 3): per cell, points are certainly covered, certainly uncovered or open;
// children re-examine only the open points, so deep cells cost little.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "point_set.hpp"
#include "rotation_cells.hpp"
#include "translation_internal.hpp"

namespace penshape::annulus::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kFirstSlices = 16;

struct Cell {
  CellBox box{};
  std::size_t sure = 0;   // weight covered everywhere in the cell (at delta)
  std::size_t upper = 0;  // sure + weight of the open points: no placement in the cell does better
  std::size_t centre = 0; // estimated count at the cell's centre (double measure)
  std::vector<std::uint32_t> open;
};

bool lower_priority(const Cell& a, const Cell& b) {
  return a.upper < b.upper || (a.upper == b.upper && a.centre < b.centre);
}

class CoverSearch {
 public:
  CoverSearch(const TemplatePolygon& p, OuterOffset outer, double delta,
              const std::vector<PointD>& points, const RotationOptions& options, std::size_t floor)
      : p_(p),
        outer_(outer),
        delta_(delta),
        original_(points),
        options_(options),
        wp_(merge_duplicates(points)),
        frame_(wp_.points),
        // Measures do not depend on delta; the box is that of the widened annulus.
        an_(prepare(p, outer, delta + annulus_margin(p, delta, points))),
        margin_(annulus_margin(p, delta, points)),
        slack_(frame_.slack(p, delta + margin_)),
        min_half_(options.translation_resolution * problem_scale(p, points)),
        best_(floor) {}

  MaxCoverResult run() {
    std::vector<std::uint32_t> all(wp_.points.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint32_t>(i);
    for (int k = 0; k < kFirstSlices; ++k) {
      Cell cell;
      cell.box = translation_domain(frame_, an_.box, slack_, -kPi + 2.0 * kPi * k / kFirstSlices,
                                    -kPi + 2.0 * kPi * (k + 1) / kFirstSlices);
      evaluate(cell, all);
      push(std::move(cell));
    }
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), lower_priority);
      Cell cell = std::move(heap_.back());
      heap_.pop_back();
      if (cell.upper <= best_) {
        heap_.clear(); // every remaining cell is bounded by this one
        break;
      }
      if (at_resolution(cell.box, options_.angle_resolution, min_half_) ||
          evaluations_ + 2 > options_.max_cells) {
        unresolved_ = std::max(unresolved_, cell.upper);
        continue;
      }
      const auto halves = split_cell(cell.box, frame_.rho(), options_.angle_resolution, min_half_);
      for (const CellBox& half : {halves.first, halves.second}) {
        Cell child;
        child.box = half;
        child.sure = cell.sure;
        evaluate(child, cell.open);
        push(std::move(child));
      }
    }
    MaxCoverResult res;
    res.placement = best_placement_;
    res.covered = std::move(best_covered_);
    std::size_t upper = std::max(best_, unresolved_);
    for (const Cell& cell : heap_) upper = std::max(upper, cell.upper);
    res.upper_bound = upper;
    return res;
  }

 private:
  void push(Cell&& cell) {
    if (cell.upper <= best_) return;
    heap_.push_back(std::move(cell));
    std::push_heap(heap_.begin(), heap_.end(), lower_priority);
  }

  // Classifies the parent's open points for this cell and tries its centre as a placement.
  void evaluate(Cell& cell, const std::vector<std::uint32_t>& parent_open) {
    ++evaluations_;
    const CellReach r = cell_reach(cell.box);
    std::size_t open_weight = 0;
    std::size_t centre = cell.sure;
    for (const std::uint32_t i : parent_open) {
      const double m = prepared_measure(an_, cell_position(frame_, r, cell.box, wp_.points[i]));
      const double move = r.translation + frame_.rho_of(i) * r.reach + slack_;
      const std::size_t w = wp_.weight[i];
      if (m + move <= delta_) {
        cell.sure += w;
        centre += w;
      } else if (m - move <= delta_ + margin_) {
        cell.open.push_back(i);
        open_weight += w;
        if (m <= delta_) centre += w;
      }
    }
    cell.upper = cell.sure + open_weight;
    cell.centre = centre;
    if (centre > best_) {
      const Placement pl = frame_.placement(r.angle, {cell.box.tx, cell.box.ty});
      std::vector<std::size_t> covered = covered_exactly(p_, outer_, delta_, pl, original_);
      if (covered.size() > best_) {
        best_ = covered.size();
        best_placement_ = pl;
        best_covered_ = std::move(covered);
      }
    }
  }

  const TemplatePolygon& p_;
  OuterOffset outer_;
  double delta_;
  const std::vector<PointD>& original_;
  const RotationOptions& options_;
  WeightedPoints wp_;
  RotatedFrame frame_;
  PreparedAnnulus an_;
  double margin_;
  double slack_;
  double min_half_;
  std::vector<Cell> heap_;
  std::size_t evaluations_ = 0;
  std::size_t best_; // the count to beat (the floor until a placement is verified)
  std::size_t unresolved_ = 0;
  Placement best_placement_;
  std::vector<std::size_t> best_covered_;
};

} // namespace

MaxCoverResult max_cover_rotation_cells(const TemplatePolygon& p, OuterOffset outer, double delta,
                                        const std::vector<PointD>& points,
                                        const RotationOptions& options) {
  return CoverSearch(p, outer, delta, points, options, 0).run();
}

DecisionResult decide_rotation_cells(const TemplatePolygon& p, OuterOffset outer, double delta,
                                     const std::vector<PointD>& points,
                                     const RotationOptions& options) {
  // Max-cover that only keeps cells able to cover every point: a verified placement covering
  // all points is a YES; no cell left is a robust NO; cells left at the resolution: UNDECIDED.
  DecisionResult r;
  r.margin = annulus_margin(p, delta, points);
  const MaxCoverResult m = CoverSearch(p, outer, delta, points, options, points.size() - 1).run();
  if (m.covered.size() == points.size()) {
    r.answer = Answer::kYes;
    r.placement = m.placement;
  } else {
    r.answer = m.upper_bound < points.size() ? Answer::kNo : Answer::kUndecided;
  }
  return r;
}

} // namespace penshape::annulus::detail
