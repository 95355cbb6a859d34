// Re-checking a recognition answer (penshape/core/verify.hpp, "Recognition answers"): the
// Hausdorff distance between the strokes' paths and the clean shape, proven by subdividing each
// side's segments until a Lipschitz bound at each piece's midpoint closes, in interval arithmetic
// with directed rounding. Every decision is a conclusive interval comparison; an inconclusive one
// subdivides further (smaller pieces), so nothing is decided by a tolerance.
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>

#include "penshape/core/verify.hpp"
#include "verify/verify_shape.hpp"

namespace penshape {
namespace {

using Iv = CGAL::Interval_nt<false>; // under the Protect_FPU_rounding guard of verify_recognition

struct Seg {
  PointD a, b;
  double lox, loy, hix, hiy; // bounding box
};

std::vector<Seg> segments_of(const std::vector<std::vector<PointD>>& chains) {
  std::vector<Seg> out;
  for (const std::vector<PointD>& c : chains) {
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (i + 1 == c.size() && c.size() > 1) break;
      const PointD a = c[i], b = c.size() > 1 ? c[i + 1] : c[i];
      out.push_back(
          {a, b, std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)});
    }
  }
  return out;
}

// An enclosure of d(p, [a, b])² for p in the box (px, py): exact formulas where the case is
// certain; otherwise the distance to the segment's line below and to its nearer end above.
Iv squared_distance(const Iv& px, const Iv& py, const Seg& s) {
  const Iv ux = Iv(s.b.x) - Iv(s.a.x), uy = Iv(s.b.y) - Iv(s.a.y);
  const Iv wx = px - Iv(s.a.x), wy = py - Iv(s.a.y);
  const Iv vx = px - Iv(s.b.x), vy = py - Iv(s.b.y);
  const Iv dot = wx * ux + wy * uy;
  const Iv len2 = CGAL::square(ux) + CGAL::square(uy);
  const Iv to_a = CGAL::square(wx) + CGAL::square(wy);
  const Iv to_b = CGAL::square(vx) + CGAL::square(vy);
  if (dot.sup() <= 0) return to_a;
  if (dot.inf() >= len2.sup()) return to_b;
  const Iv line = len2.inf() > 0 ? CGAL::square(ux * wy - uy * wx) / len2 : Iv(0.0);
  if (dot.inf() > 0 && dot.sup() < len2.inf()) return line;
  return Iv(std::max(0.0, line.inf()), std::min(to_a.sup(), to_b.sup()));
}

enum class Outcome { kCovered, kRefuted, kUnproven };

struct Finding {
  Outcome outcome = Outcome::kCovered;
  PointD at;
  double lower = 0.0; // a lower bound on the distance at `at` (refuted / unproven)
};

// sup over the chains' points of d(., target) <= budget, or a point where it is refuted
// (d > refute) or where the subdivision gave up.
class Directed {
 public:
  Directed(const std::vector<Seg>& target, double budget, double refute, const VerifyLimits& lim,
           std::size_t& cells)
      : target_(target),
        budget_(budget),
        refute2_(CGAL::square(Iv(refute)).sup()),
        lim_(lim),
        cells_(cells) {}

  // A refutation anywhere in the chain wins over an unproven piece (the first one is kept).
  Finding chain(const std::vector<PointD>& c) {
    Finding unproven;
    for (std::size_t i = 0; i == 0 || i + 1 < c.size(); ++i) {
      const Finding f = segment(c[i], c.size() > 1 ? c[i + 1] : c[i]);
      if (f.outcome == Outcome::kRefuted) return f;
      if (f.outcome == Outcome::kUnproven && unproven.outcome == Outcome::kCovered) unproven = f;
    }
    return unproven;
  }

 private:
  struct Piece {
    double u0, u1;
    int depth;
  };

  // A piece is covered (every point within budget of the target), refuted (its midpoint beyond
  // `refute`), or split; it stops splitting, unproven, when it can neither be covered (every
  // point beyond budget) nor refuted (every point within refute), or at the limits.
  Finding segment(PointD p, PointD q) {
    const Iv dx = Iv(q.x) - Iv(p.x), dy = Iv(q.y) - Iv(p.y);
    const Iv len = CGAL::sqrt(CGAL::square(dx) + CGAL::square(dy));
    Finding unproven;
    std::vector<Piece> todo{{0.0, 1.0, 0}};
    while (!todo.empty()) {
      const Piece k = todo.back();
      todo.pop_back();
      const double u = 0.5 * (k.u0 + k.u1); // dyadic: exact
      const Iv mx = Iv(p.x) + Iv(u) * dx, my = Iv(p.y) + Iv(u) * dy;
      const Iv half = len * (Iv(k.u1) - Iv(k.u0)) / Iv(2.0); // every point within it of m
      ++cells_;
      const Iv room = Iv(budget_) - half;
      if (room.inf() > 0 && covered(mx, my, CGAL::square(room).inf())) continue;
      const PointD at{0.5 * (mx.inf() + mx.sup()), 0.5 * (my.inf() + my.sup())};
      const Iv d = CGAL::sqrt(nearest(mx, my));
      if (CGAL::square(d).inf() > refute2_) return {Outcome::kRefuted, at, d.inf()};
      const bool may_cover = (d - half).inf() <= budget_;
      const bool may_refute = CGAL::square(d + half).sup() > refute2_;
      if ((!may_cover && !may_refute) || k.depth >= lim_.max_depth || cells_ >= lim_.max_cells) {
        if (unproven.outcome == Outcome::kCovered) unproven = {Outcome::kUnproven, at, d.inf()};
        if (cells_ >= lim_.max_cells) return unproven;
        continue;
      }
      todo.push_back({k.u0, u, k.depth + 1});
      todo.push_back({u, k.u1, k.depth + 1});
    }
    return unproven;
  }

  // Some target segment certainly within sqrt(limit2) of every point of the box?
  bool covered(const Iv& mx, const Iv& my, double limit2) {
    if (hint_ < target_.size() && squared_distance(mx, my, target_[hint_]).sup() <= limit2) {
      return true;
    }
    const double reach = std::sqrt(limit2);
    for (std::size_t i = 0; i < target_.size(); ++i) {
      const Seg& s = target_[i];
      if (s.lox - mx.sup() > reach || mx.inf() - s.hix > reach || s.loy - my.sup() > reach ||
          my.inf() - s.hiy > reach) {
        continue;
      }
      if (squared_distance(mx, my, s).sup() <= limit2) {
        hint_ = i;
        return true;
      }
    }
    return false;
  }

  // An enclosure of min over the targets of d².
  Iv nearest(const Iv& mx, const Iv& my) const {
    double lo = INFINITY, hi = INFINITY;
    for (const Seg& s : target_) {
      const Iv d2 = squared_distance(mx, my, s);
      lo = std::min(lo, d2.inf());
      hi = std::min(hi, d2.sup());
    }
    return Iv(lo, hi);
  }

  const std::vector<Seg>& target_;
  double budget_;
  double refute2_;
  const VerifyLimits& lim_;
  std::size_t& cells_;
  std::size_t hint_ = 0;
};

std::string point_text(PointD p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// The parts one after the other.
std::string joined(std::initializer_list<std::string> parts) {
  std::string out;
  for (const std::string& p : parts) out += p;
  return out;
}

void check_claim(const std::vector<std::vector<PointD>>& strokes, const RecognitionClaim& c) {
  if (!(c.epsilon > 0) || !std::isfinite(c.epsilon)) {
    throw InvalidInput("recognition answer: epsilon must be positive and finite");
  }
  if (c.bound && !std::isfinite(*c.bound)) {
    throw InvalidInput("recognition answer: the bound must be finite");
  }
  if (!(c.pen_radius >= 0) || !std::isfinite(c.pen_radius)) {
    throw InvalidInput("recognition answer: the pen radius must be finite and >= 0");
  }
  if (strokes.empty()) throw InvalidInput("recognition answer: no strokes");
  for (const auto& s : strokes) {
    if (s.empty()) throw InvalidInput("recognition answer: an empty stroke");
    for (const PointD& p : s) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        throw InvalidInput("recognition answer: a stroke point is not finite");
      }
    }
  }
}

} // namespace

VerifyReport verify_recognition(const std::vector<std::vector<PointD>>& strokes,
                                const RecognitionClaim& claim, const VerifyLimits& limits) {
  VerifyReport rep;
  if (claim.shape == ShapeClass::kFreeform) {
    rep.status = VerifyStatus::kVerified;
    rep.message = "verified (freeform claims no shape)";
    return rep;
  }
  check_claim(strokes, claim);
  const double eps = claim.epsilon;
  if (claim.bound && !(*claim.bound >= 0 && *claim.bound <= eps)) {
    rep.status = VerifyStatus::kRefuted;
    rep.message =
        joined({"the answer's bound ", number_text(*claim.bound),
                *claim.bound < 0 ? " is negative" : " exceeds eps = " + number_text(eps)});
    return rep;
  }
  // What the answer claims of H: its bound, else eps.
  const double claimed = claim.bound ? *claim.bound : eps;
  const std::string name = claim.bound ? "the bound" : "eps";
  const verify::ShapeChains shape = verify::shape_chains(claim.shape, claim.params, eps / 1024.0);
  const CGAL::Protect_FPU_rounding<true> rounding;
  // Both directions against the chord polylines: sup d <= claimed - sigma there gives <= claimed
  // on the true shape. A point farther than claimed + sigma + r from the other side refutes even
  // the inks: it is a point of one ink at distance > claimed from the other ink.
  const double budget = -(Iv(-claimed) + Iv(shape.deviation)).sup(); // rounded down
  const double refute = (Iv(claimed) + Iv(shape.deviation) + Iv(claim.pen_radius)).sup();
  if (!(budget > 0)) {
    rep.message = joined({"the clean shape's chord deviation ", number_text(shape.deviation),
                          " leaves nothing of ", name, " = ", number_text(claimed)});
    return rep;
  }
  const std::vector<Seg> stroke_segs = segments_of(strokes);
  const std::vector<Seg> shape_segs = segments_of(shape.chains);
  Directed to_shape(shape_segs, budget, refute, limits, rep.cells);
  Directed to_stroke(stroke_segs, budget, refute, limits, rep.cells);
  for (int side = 0; side < 2; ++side) {
    const auto& chains = side == 0 ? strokes : shape.chains;
    Directed& d = side == 0 ? to_shape : to_stroke;
    for (const std::vector<PointD>& c : chains) {
      const Finding f = d.chain(c);
      if (f.outcome == Outcome::kCovered) continue;
      const std::string what = side == 0 ? "the stroke's point " : "the clean shape's point ";
      const std::string other = side == 0 ? "the clean shape" : "the strokes";
      if (f.outcome == Outcome::kRefuted) {
        rep.status = VerifyStatus::kRefuted;
        rep.message = joined(
            {what, point_text(f.at), " is ", number_text(f.lower), " from ", other,
             ": farther than ", name, " + r = ", number_text(claimed + claim.pen_radius),
             ", so the inks are farther than ", name, " = ", number_text(claimed), " apart"});
      } else {
        rep.status = VerifyStatus::kUnproven;
        rep.message = joined({"the paths are not proven within ", name, " = ", number_text(claimed),
                              " near ", what, point_text(f.at), " (at least ", number_text(f.lower),
                              " from ", other, ")"});
      }
      return rep;
    }
  }
  rep.status = VerifyStatus::kVerified;
  rep.message = "verified";
  return rep;
}

} // namespace penshape
