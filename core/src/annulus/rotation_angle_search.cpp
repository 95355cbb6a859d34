// Branch and bound over the rotation angle with the translation solvers (rotation.hpp, method 2):
// decision, minimum width and max-cover, any outer offset the translation solvers take.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <vector>

#include "rotation_internal.hpp"
#include "translation_internal.hpp"

namespace penshape::annulus::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kFirstIntervals = 8;

struct AngleNode {
  double lo, hi;
  double key; // decision: width of the best placement seen (smaller first); min width: lower bound
  bool operator<(const AngleNode& o) const { return key > o.key; } // min-heap on key
};

} // namespace

DecisionResult decide_rotation_angles(const TemplatePolygon& p, OuterOffset outer, double delta,
                                      const std::vector<PointD>& points,
                                      const RotationOptions& options) {
  DecisionResult r;
  r.margin = annulus_margin(p, delta, points);
  const RotatedFrame frame(points);
  const double slack = frame.slack(p, delta + 2.0 * kPi * frame.rho());
  std::size_t evaluations = 0;
  bool unresolved = false;
  std::priority_queue<AngleNode> queue;
  // Drops the interval on a robust NO, sets r to kYes on a verified witness, else queues it.
  auto evaluate = [&](double lo, double hi) {
    const RotatedFrame::Angle a = RotatedFrame::angle(0.5 * (lo + hi));
    const double reach = angle_reach(a, lo, hi);
    const std::vector<PointD> rotated = frame.rotated(a);
    ++evaluations;
    // The widened decision covers every angle of the interval (and delta + margin).
    const DecisionResult wide =
        decide_translation(p, outer, delta + r.margin + frame.rho() * reach + slack, rotated);
    if (wide.answer == Answer::kNo) return;
    double key = delta + frame.rho() * reach;
    // A translation witness becomes a placement with the rational rotation u; checked exactly.
    auto verified = [&](const DecisionResult& d) {
      if (d.answer != Answer::kYes) return false;
      const Placement pl = frame.placement(a, {d.placement.tx, d.placement.ty});
      const double w = width_at(p, outer, pl, points);
      key = std::min(key, w);
      if (w > delta + slack ||
          covered_exactly(p, outer, delta, pl, points).size() != points.size()) {
        return false;
      }
      r.answer = Answer::kYes;
      r.placement = pl;
      return true;
    };
    if (verified(wide) || verified(decide_translation(p, outer, delta, rotated))) return;
    queue.push({lo, hi, key});
  };
  for (int k = 0; k < kFirstIntervals && r.answer != Answer::kYes; ++k) {
    evaluate(-kPi + 2.0 * kPi * k / kFirstIntervals, -kPi + 2.0 * kPi * (k + 1) / kFirstIntervals);
  }
  while (!queue.empty() && r.answer != Answer::kYes) {
    const AngleNode node = queue.top();
    queue.pop();
    if (0.5 * (node.hi - node.lo) < options.angle_resolution ||
        evaluations + 2 > options.max_evaluations) {
      unresolved = true; // its bounds stand: neither NO nor YES for this interval
      continue;
    }
    const double mid = 0.5 * (node.lo + node.hi);
    evaluate(node.lo, mid);
    if (r.answer != Answer::kYes) evaluate(mid, node.hi);
  }
  if (r.answer != Answer::kYes) r.answer = unresolved ? Answer::kUndecided : Answer::kNo;
  return r;
}

MinWidthResult min_width_rotation_angles(const TemplatePolygon& p, OuterOffset outer,
                                         const std::vector<PointD>& points,
                                         const MinWidthOptions& options,
                                         const RotationOptions& rotation) {
  MinWidthResult res;
  const RotatedFrame frame(points);
  res.placement = centred_placement(p, points);
  const double w0 = width_at(p, outer, res.placement, points);
  double ub = certify_width(p, outer, res.placement, w0, annulus_margin(p, w0, points), points);
  const double slack = frame.slack(p, ub);
  const double scale = problem_scale(p, points);
  const double tol = std::max({options.absolute_tolerance, options.relative_tolerance * scale,
                               4.0 * annulus_margin(p, ub, points)});
  std::size_t evaluations = 0;
  std::priority_queue<AngleNode> queue;
  double unresolved_lb = INFINITY;
  auto evaluate = [&](double lo, double hi) {
    const RotatedFrame::Angle a = RotatedFrame::angle(0.5 * (lo + hi));
    const double reach = angle_reach(a, lo, hi);
    const double spread = frame.rho() * reach + slack;
    ++evaluations;
    // The interval's bound is no sharper than its spread: solve only that precisely.
    MinWidthOptions o = options;
    o.absolute_tolerance = std::max(options.absolute_tolerance, 0.25 * spread);
    const MinWidthResult t = min_width_translation(p, outer, frame.rotated(a), o);
    res.decisions += t.decisions;
    const Placement pl = frame.placement(a, {t.placement.tx, t.placement.ty});
    const double w = width_at(p, outer, pl, points);
    if (w < ub) {
      const double cw = certify_width(p, outer, pl, w, annulus_margin(p, w, points), points);
      if (cw < ub) {
        ub = cw;
        res.placement = pl;
      }
    }
    queue.push({lo, hi, std::max(0.0, t.delta_lower - spread)});
  };
  for (int k = 0; k < kFirstIntervals; ++k) {
    evaluate(-kPi + 2.0 * kPi * k / kFirstIntervals, -kPi + 2.0 * kPi * (k + 1) / kFirstIntervals);
  }
  while (!queue.empty()) {
    const AngleNode node = queue.top();
    if (node.key >= ub - tol) break; // every other interval's bound is at least as high
    queue.pop();
    if (0.5 * (node.hi - node.lo) < rotation.angle_resolution ||
        evaluations + 2 > rotation.max_evaluations) {
      unresolved_lb = std::min(unresolved_lb, node.key);
      continue;
    }
    const double mid = 0.5 * (node.lo + node.hi);
    evaluate(node.lo, mid);
    evaluate(mid, node.hi);
  }
  double lb = unresolved_lb;
  if (!queue.empty()) lb = std::min(lb, queue.top().key);
  res.delta_upper = ub;
  res.delta_lower = std::min(lb, ub);
  return res;
}

MaxCoverResult max_cover_rotation_angles(const TemplatePolygon& p, OuterOffset outer, double delta,
                                         const std::vector<PointD>& points,
                                         const RotationOptions& options) {
  const RotatedFrame frame(points);
  const double margin = annulus_margin(p, delta, points);
  const double slack = frame.slack(p, delta + 2.0 * kPi * frame.rho());
  MaxCoverResult res;
  std::size_t evaluations = 0;
  std::size_t unresolved = 0;
  struct Node {
    double lo, hi;
    std::size_t upper;
    bool operator<(const Node& o) const { return upper < o.upper; } // max-heap on the bound
  };
  std::priority_queue<Node> queue;
  auto evaluate = [&](double lo, double hi) {
    const RotatedFrame::Angle a = RotatedFrame::angle(0.5 * (lo + hi));
    const double reach = angle_reach(a, lo, hi);
    const std::vector<PointD> rotated = frame.rotated(a);
    ++evaluations;
    // Robust bound for every angle of the interval (and delta + margin).
    const std::size_t upper =
        max_cover_translation(p, outer, delta + margin + frame.rho() * reach + slack, rotated)
            .upper_bound;
    if (upper <= res.covered.size()) return;
    const MaxCoverResult here = max_cover_translation(p, outer, delta, rotated);
    const Placement pl = frame.placement(a, {here.placement.tx, here.placement.ty});
    std::vector<std::size_t> covered = covered_exactly(p, outer, delta, pl, points);
    if (covered.size() > res.covered.size() || res.covered.empty()) {
      res.covered = std::move(covered);
      res.placement = pl;
    }
    if (upper > res.covered.size()) queue.push({lo, hi, upper});
  };
  for (int k = 0; k < kFirstIntervals; ++k) {
    evaluate(-kPi + 2.0 * kPi * k / kFirstIntervals, -kPi + 2.0 * kPi * (k + 1) / kFirstIntervals);
  }
  while (!queue.empty()) {
    const Node node = queue.top();
    if (node.upper <= res.covered.size()) break; // every other interval is bounded by this one
    queue.pop();
    if (0.5 * (node.hi - node.lo) < options.angle_resolution ||
        evaluations + 2 > options.max_evaluations) {
      unresolved = std::max(unresolved, node.upper);
      continue;
    }
    const double mid = 0.5 * (node.lo + node.hi);
    evaluate(node.lo, mid);
    evaluate(mid, node.hi);
  }
  res.upper_bound = std::max(res.covered.size(), unresolved);
  if (!queue.empty()) res.upper_bound = std::max(res.upper_bound, queue.top().upper);
  return res;
}

} // namespace penshape::annulus::detail
