#include "yes_certificate.hpp"

#include <algorithm>
#include <utility>

#include <optional>
#include "certified.hpp"
#include "douglas_peucker.hpp"
#include "grid_frame.hpp"
#include "level_set_check.hpp"

namespace penshape::fast {
namespace {

// d(v, region) < bound, certified (inside counts as distance 0).
bool within(const SegmentIndex& region, IPt v, double bound) {
  if (region.winding(v) > 0) return true;
  return some_edge_closer(region, at_point(v), bound);
}

} // namespace

namespace {

// A box around `t` grown by `by` on every side.
Window grown(const Window& t, double by) {
  return {t.lo_x - by, t.lo_y - by, t.hi_x + by, t.hi_y + by};
}

// verify_yes, with the level-set walks limited to the neighbourhood of `changed` when given
// (verify_yes_after_drop says why that suffices).
bool verify(const YesCheckInput& in, const YesCandidate& c, const Window* changed,
            const CancelHook& cancel) {
  const IRegion& p = c.p;
  if (p.empty() || !c.certifiable) return false;
  const SegmentIndex& pi = c.index;

  // The levels are doubles rounded down from the exact bounds, and are then taken as exact.
  const double level_a = fast::level_a(in);                        // <= eps - η
  const double level_b = sub_down(in.radius.lo, -in.tolerance.lo); // <= r + eps
  if (level_a <= 1.0 || level_b <= 1.0) return false;

  // (A2) no component of P lies wholly where d(·, Q_s) >= level_a (in.q is Q_s or Q̃).
  for (const IPolygon& poly : p) {
    if (!within(*in.q, poly.outer.front(), level_a)) return false;
  }
  // (B2) no component of Q lies wholly where d(·, P) >= level_b: its grid vertex is within
  // η0 = 3/4 of the true one.
  const double level_b_vertex = sub_down(level_b, kInputRounding);
  for (const IPt& v : in.q_component_vertices) {
    if (!within(pi, v, level_b_vertex)) return false;
  }
  // (A1) the level set {d(·, Q_s) = level_a} keeps distance > r (r <= radius.hi) from P.
  const Window near_a = changed ? grown(*changed, in.radius.hi) : Window{};
  const auto a1 = [&] {
    return level_set_avoids(
        {in.q, level_a, &pi, in.radius.hi, in.max_sagitta, changed ? &near_a : nullptr, in.memo},
        cancel);
  };
  // (B1) the level set {d(·, P) = level_b} stays outside Q: farther than η0 from Q̃ (the
  // unsimplified grid input, so the simplification does not eat into this margin).
  const Window near_b = changed ? grown(*changed, level_b) : Window{};
  const auto b1 = [&] {
    return level_set_avoids({&pi, level_b, in.q_grid, kInputRounding, in.max_sagitta,
                             changed ? &near_b : nullptr, nullptr, true},
                            cancel);
  };
  // Both must hold, in either order. A whole check walks (B1) first: it is the cheaper walk
  // (P has fewer edges than Q_s; KAZ at r = w/30: 0.4 vs 1.4 ms), and a P that fails, as the
  // chains' candidates do on a NO, mostly fails it (KAZ at eps = r/4: 31 -> 26 ms per decision).
  // The simplifier's local checks keep (A1) first, as before.
  return changed ? (a1() && b1()) : (b1() && a1());
}

} // namespace

YesCandidate::YesCandidate(const YesCheckInput& in, IRegion region)
    : p(std::move(region)),
      index(flatten(p), in.radius.lo / 2.0),
      certifiable(!p.empty() && is_certifiable_region(index)) {}

bool verify_yes(const YesCheckInput& in, const IRegion& p, const CancelHook& cancel) {
  return verify(in, YesCandidate(in, p), nullptr, cancel);
}

bool verify_yes(const YesCheckInput& in, const YesCandidate& c, const CancelHook& cancel) {
  return verify(in, c, nullptr, cancel);
}

bool verify_yes_after_drop(const YesCheckInput& in, const IRegion& p, IPt a, IPt v, IPt b,
                           const CancelHook& cancel) {
  const Window triangle{static_cast<double>(std::min({a.x, v.x, b.x})),
                        static_cast<double>(std::min({a.y, v.y, b.y})),
                        static_cast<double>(std::max({a.x, v.x, b.x})),
                        static_cast<double>(std::max({a.y, v.y, b.y}))};
  return verify(in, YesCandidate(in, p), &triangle, cancel);
}

CertifiedInput certified_input(const IRings& q_grid, double tolerance, double cell) {
  CertifiedInput out;
  if (q_grid.empty()) return out;
  // Narrow features can make a coarse simplification cross itself: retry finer.
  for (double tol = tolerance; tol >= tolerance / 8.0 && !out.index; tol /= 2.0) {
    if (auto q_dp = simplify_rings_checked(q_grid, tol)) {
      out.index.emplace(*q_dp, cell);
      out.eta = add_up(kInputRounding, tol);
      if (!is_certifiable_region(*out.index)) out.index.reset();
    }
  }
  if (!out.index) {
    out.eta = kInputRounding;
    out.index.emplace(q_grid, cell);
    if (!is_certifiable_region(*out.index)) out.index.reset();
  }
  return out;
}

YesCheckInput yes_check_input(const CertifiedInput& a, const SegmentIndex& q_grid,
                              const GridFrame& frame, const PolygonSet& q,
                              const DeconstructParams& params, double max_sagitta) {
  std::vector<IPt> q_vertices;
  q_vertices.reserve(q.polygons.size());
  for (const auto& poly : q.polygons) q_vertices.push_back(frame.round(poly.outer.front()));
  return {&*a.index,
          a.eta,
          &q_grid,
          std::move(q_vertices),
          frame.bounds(params.radius),
          frame.bounds(params.tolerance),
          max_sagitta};
}

} // namespace penshape::fast
