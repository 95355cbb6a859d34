// On-line containment decision under translation (Section 4) with the pruning of Section 4.3,
// for convex templates and, with the round outer offset, simple ones (Section 5).
//
// Why the same structures serve simple templates: a translate containing every point can be
// moved until some point meets the region's boundary, so a placement exists iff some point's
// boundary-anchored set survives every other point (the off-line decision's argument,
// translation.cpp). For a simple template the prepared annulus has no separate hole: every
// boundary piece of the delta-wide region (the 2m offset segments and m vertex arcs) is in
// outer_curve, and inner_curve is empty, so each point keeps one set per piece. Pruning is
// unchanged: a point whose sets all empty can be on the boundary of no containing placement.
#include "penshape/core/annulus/online.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "prepared_annulus.hpp"
#include "translation_internal.hpp"

namespace penshape::annulus {

using namespace detail;

struct OnlineContainment::State {
  // Placements with `point` on the inner (0) or outer (1) boundary containing every point
  // applied so far, per boundary piece. Points deleted before this structure was created are
  // applied lazily (queue[0, missing_until)).
  struct Structure {
    std::size_t point = 0;
    std::size_t missing_until = 0;
    std::vector<IntervalSet> sets[2];
  };

  TemplatePolygon p;
  OuterOffset outer;
  double delta;
  PreparedAnnulus an;
  std::vector<PointD> pts;
  std::vector<Structure> structures; // one per point, by index
  std::vector<std::size_t> active;
  std::vector<std::size_t> queue; // deleted points in order of deletion
  Answer answer = Answer::kUndecided;
  Placement witness;
  bool has_witness = false;
  std::size_t max_active = 0;

  const Curve& curve(int which) const { return which == 0 ? an.inner_curve : an.outer_curve; }

  // Intersects structure s with the containing sets of point j; false when it became empty.
  bool apply(Structure& s, std::size_t j) const {
    const PointD d = pts[j] - pts[s.point];
    bool any = false;
    for (int w = 0; w < 2; ++w) {
      const Curve& c = curve(w);
      for (std::size_t k = 0; k < c.size(); ++k) {
        if (s.sets[w][k].empty()) continue;
        if (d.x == 0.0 && d.y == 0.0) {
          any = true; // the same location is contained wherever the anchor is
          continue;
        }
        s.sets[w][k] = intersect(s.sets[w][k], member_set(an, c[k], d));
        any = any || !s.sets[w][k].empty();
      }
    }
    return any;
  }

  static void check_finite(PointD q, std::size_t index) {
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) {
      throw InvalidInput("point " + std::to_string(index) + " is not finite");
    }
  }

  // Records q and updates the structures with it (the O(h m^2) part); false once the answer is
  // a (final) NO.
  bool push(PointD q) {
    const std::size_t idx = pts.size();
    pts.push_back(q);
    structures.emplace_back();
    if (answer == Answer::kNo) return false; // final
    // Update the active structures with the new point; discard the ones that empty.
    std::vector<std::size_t> survivors;
    for (std::size_t s : active) {
      if (apply(structures[s], idx)) {
        survivors.push_back(s);
      } else {
        queue.push_back(s);
      }
    }
    // The new point's own structure, updated by the active points only.
    Structure& ns = structures[idx];
    ns.point = idx;
    ns.missing_until = queue.size();
    bool alive = true;
    for (int w = 0; w < 2; ++w) {
      const Curve& c = curve(w);
      ns.sets[w].resize(c.size());
      for (std::size_t k = 0; k < c.size(); ++k) ns.sets[w][k] = {{c[k].lo(), c[k].hi()}};
      if (c.empty()) ns.sets[w].clear();
    }
    for (std::size_t s : survivors) {
      if (!apply(ns, s)) {
        alive = false;
        break;
      }
    }
    if (alive) {
      survivors.push_back(idx);
    } else {
      queue.push_back(idx);
    }
    active.swap(survivors);
    max_active = std::max(max_active, active.size());
    if (active.empty()) {
      answer = Answer::kNo;
      return false;
    }
    return true;
  }

  // The answer after the points `fresh` were pushed: the witness if it still holds for all of
  // them, else reconciliation and a new witness search over all points.
  Answer decide(std::span<const PointD> fresh) {
    // The last witness may still hold.
    if (has_witness && std::all_of(fresh.begin(), fresh.end(), [&](PointD q) {
          return annulus_contains_exactly(p, outer, delta, witness, q);
        })) {
      return answer = Answer::kYes;
    }
    has_witness = false;
    // Reconcile: apply the queued points a structure has not seen; a non-empty result then holds
    // exactly the placements with its point on the boundary that contain every point (with the
    // widened annulus). The first survivor means a witness should exist: search it with the
    // narrowed annulus (translation.cpp) and check it exactly.
    std::vector<std::size_t> keep;
    bool survivor = false;
    for (std::size_t a = 0; a < active.size(); ++a) {
      const std::size_t s = active[a];
      Structure& st = structures[s];
      bool ok = true;
      if (!survivor) {
        for (std::size_t t = 0; t < st.missing_until && ok; ++t) ok = apply(st, queue[t]);
        st.missing_until = 0;
      }
      if (!ok) {
        queue.push_back(s);
        continue;
      }
      keep.push_back(s);
      survivor = true;
    }
    Answer result = Answer::kNo;
    if (survivor) {
      result = Answer::kUndecided;
      if (find_translation_witness(p, outer, delta, pts, witness)) {
        has_witness = true;
        result = Answer::kYes;
      }
    }
    active.swap(keep);
    return answer = result;
  }

  Answer add(PointD q) {
    check_finite(q, pts.size());
    if (!push(q)) return answer;
    return decide(std::span<const PointD>(&q, 1));
  }

  Answer add_all(std::span<const PointD> qs) {
    for (std::size_t i = 0; i < qs.size(); ++i) check_finite(qs[i], pts.size() + i);
    bool no = false;
    for (const PointD& q : qs) no = !push(q) || no; // after a NO, points are only recorded
    if (no || qs.empty()) return answer;
    return decide(qs);
  }
};

OnlineContainment::OnlineContainment(const TemplatePolygon& p, OuterOffset outer, double delta,
                                     double coordinate_magnitude, const Limits& limits) {
  if (!p.convex() && outer == OuterOffset::kLinearized) {
    throw InvalidInput(
        "the on-line decision with the linearized outer offset needs a convex "
        "template (simple templates: kRound)");
  }
  validate_delta(delta, limits);
  if (!std::isfinite(coordinate_magnitude) || coordinate_magnitude < 0.0) {
    throw InvalidInput("coordinate magnitude must be finite and non-negative");
  }
  const double margin = annulus_margin(p, delta, {PointD{coordinate_magnitude, 0.0}});
  state_ = std::make_unique<State>(State{p,
                                         outer,
                                         delta,
                                         prepare(p, outer, widened(delta, margin)),
                                         {},
                                         {},
                                         {},
                                         {},
                                         Answer::kUndecided,
                                         {},
                                         false,
                                         0});
}

OnlineContainment::~OnlineContainment() = default;
OnlineContainment::OnlineContainment(OnlineContainment&&) noexcept = default;
OnlineContainment& OnlineContainment::operator=(OnlineContainment&&) noexcept = default;

Answer OnlineContainment::add(PointD q) { return state_->add(q); }
Answer OnlineContainment::add_all(std::span<const PointD> points) {
  return state_->add_all(points);
}
Answer OnlineContainment::answer() const { return state_->answer; }
const Placement& OnlineContainment::placement() const { return state_->witness; }
std::size_t OnlineContainment::points() const { return state_->pts.size(); }
std::size_t OnlineContainment::active_structures() const { return state_->active.size(); }
std::size_t OnlineContainment::max_active_structures() const { return state_->max_active; }

} // namespace penshape::annulus
