// Minimum width under translation and rotation by branch and bound over (tx, ty, theta) cells
// (rotation.hpp, method 3). The width at a placement is the largest measure over the points; each
// measure is 1-Lipschitz in the point, so over a cell it is at least (measure at the centre) minus
// (how far the cell moves the point). A point whose largest possible measure in the cell is below
// another point's smallest one is never the widest there, nor in any sub-cell: children drop it.
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

struct WidthCell {
  CellBox box{};
  double lower = 0.0; // no placement in the cell has a smaller width
  std::vector<std::uint32_t> open;
};

bool lower_priority(const WidthCell& a, const WidthCell& b) { return a.lower > b.lower; }

class WidthSearch {
 public:
  WidthSearch(const TemplatePolygon& p, OuterOffset outer, const std::vector<PointD>& points,
              const MinWidthOptions& options, const RotationOptions& rotation)
      : p_(p),
        outer_(outer),
        original_(points),
        options_(options),
        rotation_(rotation),
        points_(merge_duplicates(points).points),
        frame_(points_),
        min_half_(rotation.translation_resolution * problem_scale(p, points)) {}

  MinWidthResult run() {
    res_.placement = centred_placement(p_, original_);
    const double w0 = width_at(p_, outer_, res_.placement, original_);
    upper_ =
        certify_width(p_, outer_, res_.placement, w0, annulus_margin(p_, w0, original_), original_);
    an_ = prepare(p_, outer_, upper_);
    slack_ = frame_.slack(p_, upper_);
    tol_ = std::max({options_.absolute_tolerance,
                     options_.relative_tolerance * problem_scale(p_, original_),
                     4.0 * annulus_margin(p_, upper_, original_)});
    std::vector<std::uint32_t> all(points_.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint32_t>(i);
    // An optimal placement holds every point in its upper_-annulus, whose box is an_.box.
    for (int k = 0; k < kFirstSlices; ++k) {
      WidthCell cell;
      cell.box = translation_domain(frame_, an_.box, slack_, -kPi + 2.0 * kPi * k / kFirstSlices,
                                    -kPi + 2.0 * kPi * (k + 1) / kFirstSlices);
      evaluate(cell, all);
      push(std::move(cell));
    }
    double unresolved = INFINITY;
    while (!heap_.empty()) {
      if (heap_.front().lower >= upper_ - tol_) break; // the best cell cannot improve enough
      std::pop_heap(heap_.begin(), heap_.end(), lower_priority);
      WidthCell cell = std::move(heap_.back());
      heap_.pop_back();
      if (at_resolution(cell.box, rotation_.angle_resolution, min_half_) ||
          evaluations_ + 2 > rotation_.max_cells) {
        unresolved = std::min(unresolved, cell.lower);
        continue;
      }
      const auto halves = split_cell(cell.box, frame_.rho(), rotation_.angle_resolution, min_half_);
      for (const CellBox& half : {halves.first, halves.second}) {
        WidthCell child;
        child.box = half;
        evaluate(child, cell.open);
        push(std::move(child));
      }
    }
    double lower = std::min(unresolved, pruned_);
    if (!heap_.empty()) lower = std::min(lower, heap_.front().lower);
    res_.delta_upper = upper_;
    res_.delta_lower = std::max(0.0, std::min(lower, upper_));
    res_.decisions = evaluations_;
    return res_;
  }

 private:
  void push(WidthCell&& cell) {
    if (cell.lower >= upper_ - tol_) {
      pruned_ = std::min(pruned_, cell.lower);
      return;
    }
    heap_.push_back(std::move(cell));
    std::push_heap(heap_.begin(), heap_.end(), lower_priority);
  }

  void evaluate(WidthCell& cell, const std::vector<std::uint32_t>& parent_open) {
    ++evaluations_;
    const CellReach r = cell_reach(cell.box);
    measures_.clear();
    double lower = -INFINITY;
    double centre = -INFINITY;
    for (const std::uint32_t i : parent_open) {
      const double m = prepared_measure(an_, cell_position(frame_, r, cell.box, points_[i]));
      const double move = r.translation + frame_.rho_of(i) * r.reach + slack_;
      measures_.push_back({m - move, m + move});
      lower = std::max(lower, m - move);
      centre = std::max(centre, m);
    }
    cell.lower = std::max(0.0, lower);
    for (std::size_t k = 0; k < parent_open.size(); ++k) {
      if (measures_[k].second >= lower) cell.open.push_back(parent_open[k]);
    }
    if (centre < upper_ - 0.25 * tol_) {
      const Placement pl = frame_.placement(r.angle, {cell.box.tx, cell.box.ty});
      const double w = width_at(p_, outer_, pl, original_);
      if (w < upper_) {
        const double cw =
            certify_width(p_, outer_, pl, w, annulus_margin(p_, w, original_), original_);
        if (cw < upper_) {
          upper_ = cw;
          res_.placement = pl;
        }
      }
    }
  }

  const TemplatePolygon& p_;
  OuterOffset outer_;
  const std::vector<PointD>& original_;
  const MinWidthOptions& options_;
  const RotationOptions& rotation_;
  std::vector<PointD> points_; // distinct
  RotatedFrame frame_;
  PreparedAnnulus an_;
  double slack_ = 0.0;
  double tol_ = 0.0;
  double min_half_;
  double upper_ = INFINITY;
  double pruned_ = INFINITY;
  std::vector<WidthCell> heap_;
  std::vector<std::pair<double, double>> measures_;
  std::size_t evaluations_ = 0;
  MinWidthResult res_;
};

} // namespace

MinWidthResult min_width_rotation_cells(const TemplatePolygon& p, OuterOffset outer,
                                        const std::vector<PointD>& points,
                                        const MinWidthOptions& options,
                                        const RotationOptions& rotation) {
  return WidthSearch(p, outer, points, options, rotation).run();
}

} // namespace penshape::annulus::detail
