// Translation-only placement: decision, minimum width and max-cover (anchored sweep, Fig. 3).
#include "penshape/core/annulus/translation.hpp"

#include <algorithm>
#include <cmath>

#include "translation_internal.hpp"

namespace penshape::annulus {
namespace detail {

Placement centred_placement(const TemplatePolygon& p, const std::vector<PointD>& points) {
  const Box a = bounding_box(points), b = bounding_box(p.vertices());
  Placement pl;
  pl.tx = 0.5 * (a.x0 + a.x1) - 0.5 * (b.x0 + b.x1);
  pl.ty = 0.5 * (a.y0 + a.y1) - 0.5 * (b.y0 + b.y1);
  return pl;
}

double problem_scale(const TemplatePolygon& p, const std::vector<PointD>& points) {
  const Box a = bounding_box(p.vertices()), b = bounding_box(points);
  return std::hypot(a.x1 - a.x0, a.y1 - a.y0) + std::hypot(b.x1 - b.x0, b.y1 - b.y0);
}

bool longest_interval_midpoint(const std::vector<IntervalSet>& sets, const Curve& curve,
                               double& g) {
  double best = -1.0;
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const Piece& pc = curve[k];
    const double span = pc.hi() - pc.lo();
    for (const Interval& iv : sets[k]) {
      const double len = (iv.hi - iv.lo) / span;
      if (len > best) {
        best = len;
        g = static_cast<double>(k) + (0.5 * (iv.lo + iv.hi) - pc.lo()) / span;
      }
    }
  }
  return best >= 0.0;
}

double certify_width(const TemplatePolygon& p, OuterOffset outer, const Placement& placement,
                     double width, double margin, const std::vector<PointD>& points) {
  double w = width;
  for (int attempt = 0; attempt < 60; ++attempt) {
    if (covered_exactly(p, outer, w, placement, points).size() == points.size()) return w;
    w += margin * std::ldexp(1.0, attempt / 4);
  }
  return INFINITY;
}

namespace {

struct Problem {
  const TemplatePolygon& p;
  OuterOffset outer;
  const std::vector<PointD>& original;
  WeightedPoints wp;
  std::vector<bool> hull;
  std::vector<std::size_t> order; // visiting order of the points (killers move to the front)
};

Problem make_problem(const TemplatePolygon& p, OuterOffset outer,
                     const std::vector<PointD>& points) {
  Problem pr{p, outer, points, merge_duplicates(points), {}, {}};
  pr.hull = p.convex() ? hull_boundary(pr.wp.points) : std::vector<bool>(pr.wp.points.size(), true);
  pr.order.resize(pr.wp.points.size());
  for (std::size_t i = 0; i < pr.order.size(); ++i) pr.order[i] = i;
  return pr;
}

// Anchored sweeps that intersect the containing sets of all points along each anchor curve.
// Calls accept(placement) for each anchor curve whose set stays non-empty, in order, until it
// returns true. Returns whether some placement was accepted.
template <typename Accept>
bool find_survivor(Problem& pr, const PreparedAnnulus& an, Accept&& accept) {
  const auto& pts = pr.wp.points;
  std::vector<IntervalSet> sets;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (int which = 0; which < 2; ++which) {
      // Outer boundaries only of hull points: a point on the outer boundary of a placement that
      // contains every point is on the hull of the points (convex templates).
      const Curve& curve = which == 0 ? an.outer_curve : an.inner_curve;
      if (curve.empty() || (which == 0 && !pr.hull[i])) continue;
      sets.assign(curve.size(), {});
      for (std::size_t k = 0; k < curve.size(); ++k) sets[k] = {{curve[k].lo(), curve[k].hi()}};
      bool alive = true;
      for (std::size_t t = 0; t < pr.order.size() && alive; ++t) {
        const std::size_t j = pr.order[t];
        if (j == i) continue;
        const PointD d = pts[j] - pts[i];
        bool any = false;
        for (std::size_t k = 0; k < curve.size(); ++k) {
          if (sets[k].empty()) continue;
          sets[k] = intersect(sets[k], member_set(an, curve[k], d));
          any = any || !sets[k].empty();
        }
        if (!any) {
          alive = false;
          std::swap(pr.order[t], pr.order[0]);
        }
      }
      double g = 0.0;
      if (!alive || !longest_interval_midpoint(sets, curve, g)) continue;
      const PointD y = curve_point(curve, g);
      Placement pl;
      pl.tx = pts[i].x - y.x;
      pl.ty = pts[i].y - y.y;
      if (accept(pl)) return true;
    }
  }
  return false;
}

DecisionResult decide_core(Problem& pr, double delta) {
  DecisionResult r;
  r.margin = annulus_margin(pr.p, delta, pr.original);
  // A cheap witness first.
  const Placement guess = centred_placement(pr.p, pr.original);
  if (width_at(pr.p, pr.outer, guess, pr.original) <= delta &&
      covered_exactly(pr.p, pr.outer, delta, guess, pr.original).size() == pr.original.size()) {
    r.answer = Answer::kYes;
    r.placement = guess;
    return r;
  }
  // NO is decided with the widened annulus: rounding cannot hide a placement from it.
  const PreparedAnnulus wide = prepare(pr.p, pr.outer, widened(delta, r.margin));
  if (!find_survivor(pr, wide, [](const Placement&) { return true; })) {
    r.answer = Answer::kNo;
    return r;
  }
  // Witnesses come from the narrowed annulus, where they are inside with room to spare.
  const PreparedAnnulus narrow = prepare(pr.p, pr.outer, narrowed(delta, r.margin));
  const bool yes = find_survivor(pr, narrow, [&](const Placement& pl) {
    if (covered_exactly(pr.p, pr.outer, delta, pl, pr.original).size() != pr.original.size()) {
      return false;
    }
    r.placement = pl;
    return true;
  });
  r.answer = yes ? Answer::kYes : Answer::kUndecided;
  return r;
}

void validate_all(const TemplatePolygon& p, OuterOffset outer, const std::vector<PointD>& points,
                  const Limits& limits) {
  validate_points(points, limits);
  if (!p.convex() && outer == OuterOffset::kLinearized) {
    throw InvalidInput("the linearized outer offset needs a convex template");
  }
}

} // namespace

bool find_translation_witness(const TemplatePolygon& p, OuterOffset outer, double delta,
                              const std::vector<PointD>& points, Placement& placement) {
  Problem pr = make_problem(p, outer, points);
  const double margin = annulus_margin(p, delta, points);
  const PreparedAnnulus narrow = prepare(p, outer, narrowed(delta, margin));
  return find_survivor(pr, narrow, [&](const Placement& pl) {
    if (covered_exactly(p, outer, delta, pl, points).size() != points.size()) return false;
    placement = pl;
    return true;
  });
}

} // namespace detail

using namespace detail;

DecisionResult decide_translation(const TemplatePolygon& p, OuterOffset outer, double delta,
                                  const std::vector<PointD>& points, const Limits& limits) {
  validate_all(p, outer, points, limits);
  validate_delta(delta, limits);
  Problem pr = make_problem(p, outer, points);
  return decide_core(pr, delta);
}

MinWidthResult min_width_translation(const TemplatePolygon& p, OuterOffset outer,
                                     const std::vector<PointD>& points,
                                     const MinWidthOptions& options, const Limits& limits) {
  validate_all(p, outer, points, limits);
  Problem pr = make_problem(p, outer, points);
  return detail::bisect_min_width(p, outer, points, options, [&pr](double width, const Placement&) {
    return decide_core(pr, width);
  });
}

namespace detail {
namespace {

struct SweepBest {
  std::size_t count = 0;
  Placement placement;
};

// Fig. 3: for every point, sweep both boundaries of its annulus and track the depth.
SweepBest anchored_sweep(const PreparedAnnulus& an, const WeightedPoints& wp, bool bucketing) {
  const auto& pts = wp.points;
  const std::size_t n = pts.size();
  const BucketGrid grid(pts, an.box.x1 - an.box.x0, an.box.y1 - an.box.y0);
  struct Event {
    double pos;
    long weight;
  };
  std::vector<Event> events;
  std::vector<std::size_t> nb;
  IntervalSet along;
  SweepBest best;
  std::size_t best_i = 0;
  const Curve* best_curve = nullptr;
  double best_g = 0.5;
  for (std::size_t i = 0; i < n; ++i) {
    if (bucketing) {
      grid.neighbours(i, nb);
    } else {
      nb.clear();
      for (std::size_t j = 0; j < n; ++j) {
        if (j != i) nb.push_back(j);
      }
    }
    for (const Curve* curve : {&an.inner_curve, &an.outer_curve}) {
      if (curve->empty()) continue;
      const double stride = curve == &an.outer_curve ? an.outer_stride : 1.0;
      events.clear();
      for (std::size_t j : nb) {
        const PointD d = pts[j] - pts[i];
        const long w = static_cast<long>(wp.weight[j]);
        // Global intervals of j, merged across piece ends so j is never counted twice.
        along.clear();
        for (std::size_t k = 0; k < curve->size(); ++k) {
          const Piece& pc = (*curve)[k];
          const double span = pc.hi() - pc.lo();
          for (const Interval& iv : member_set(an, pc, d)) {
            const double base = static_cast<double>(k) * stride;
            along.push_back({base + (iv.lo - pc.lo()) / span, base + (iv.hi - pc.lo()) / span});
          }
        }
        normalize(along);
        for (const Interval& iv : along) {
          events.push_back({iv.lo, w});
          events.push_back({iv.hi, -w});
        }
      }
      // Entries before exits at equal positions: the annulus is closed.
      std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
        return a.pos < b.pos || (a.pos == b.pos && a.weight > b.weight);
      });
      long cur = static_cast<long>(wp.weight[i]);
      if (static_cast<std::size_t>(cur) > best.count) {
        best.count = static_cast<std::size_t>(cur);
        best_i = i;
        best_curve = curve;
        best_g = events.empty() ? 0.5 : 0.5 * events.front().pos;
      }
      for (std::size_t e = 0; e < events.size(); ++e) {
        cur += events[e].weight;
        if (cur > 0 && static_cast<std::size_t>(cur) > best.count) {
          best.count = static_cast<std::size_t>(cur);
          best_i = i;
          best_curve = curve;
          const double next = e + 1 < events.size() ? events[e + 1].pos : events[e].pos;
          best_g = 0.5 * (events[e].pos + next);
        }
      }
    }
  }
  if (best_curve != nullptr) {
    const PointD y =
        curve_point(*best_curve, best_g, best_curve == &an.outer_curve ? an.outer_stride : 1.0);
    best.placement.tx = pts[best_i].x - y.x;
    best.placement.ty = pts[best_i].y - y.y;
  }
  return best;
}

} // namespace
} // namespace detail

MaxCoverResult max_cover_translation(const TemplatePolygon& p, OuterOffset outer, double delta,
                                     const std::vector<PointD>& points,
                                     const MaxCoverOptions& options, const Limits& limits) {
  validate_all(p, outer, points, limits);
  validate_delta(delta, limits);
  const WeightedPoints wp = merge_duplicates(points);
  const double margin = annulus_margin(p, delta, points);
  MaxCoverResult res;
  res.upper_bound =
      anchored_sweep(prepare(p, outer, widened(delta, margin)), wp, options.bucketing).count;
  const SweepBest inner =
      anchored_sweep(prepare(p, outer, narrowed(delta, margin)), wp, options.bucketing);
  res.placement = inner.placement;
  res.covered = covered_exactly(p, outer, delta, res.placement, points);
  return res;
}

} // namespace penshape::annulus
