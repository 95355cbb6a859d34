// verify_deconstruction(): the claim's parameters, then the proofs of verify.hpp for its answer,
// with a message that names what fails and where.
#include <CGAL/FPU.h>

#include <cstdio>

#include "penshape/core/verify.hpp"
#include "penshape/types/lookup_table.hpp"
#include "verify/verify_cover.hpp"
#include "verify/verify_edges.hpp"
#include "verify/verify_valid.hpp"

namespace penshape {

const char* to_string(VerifyStatus s) {
  static constexpr LookupTable<VerifyStatus, const char*, 3> kStatusNames{
      {{VerifyStatus::kVerified, "verified"},
       {VerifyStatus::kRefuted, "refuted"},
       {VerifyStatus::kUnproven, "unproven"}}};
  return lookup_or(kStatusNames, s, "unproven");
}

namespace {

std::string point_text(const ExactPoint& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x.get_d(), p.y.get_d());
  return buf;
}

VerifyReport report(VerifyStatus s, std::string message, std::size_t cells = 0) {
  return {s, std::move(message), cells};
}

void check_params(const DeconstructionClaim& c) {
  if (sgn(c.radius) <= 0) throw InvalidInput("radius must be > 0");
  if (sgn(c.tolerance) <= 0) throw InvalidInput("tolerance must be > 0");
  if (sgn(c.precision) <= 0 || c.precision >= c.tolerance) {
    throw InvalidInput("precision must be > 0 and < tolerance");
  }
}

// The same closed ring, possibly starting elsewhere or running the other way.
bool same_ring(const Ring& a, const Ring& b) {
  const std::size_t n = a.size();
  if (n != b.size() || n == 0) return false;
  for (std::size_t s = 0; s < n; ++s) {
    if (!(b[s] == a[0])) continue;
    bool forward = true, backward = true;
    for (std::size_t i = 0; i < n && (forward || backward); ++i) {
      forward = forward && b[(s + i) % n] == a[i];
      backward = backward && b[(s + n - i) % n] == a[i];
    }
    if (forward || backward) return true;
  }
  return false;
}

// P is Q itself (polygon by polygon, ring by ring).
bool same_region(const PolygonSet& p, const PolygonSet& q) {
  if (p.polygons.size() != q.polygons.size()) return false;
  for (std::size_t k = 0; k < p.polygons.size(); ++k) {
    const auto& a = p.polygons[k];
    const auto& b = q.polygons[k];
    if (a.holes.size() != b.holes.size() || !same_ring(a.outer, b.outer)) return false;
    for (std::size_t h = 0; h < a.holes.size(); ++h) {
      if (!same_ring(a.holes[h], b.holes[h])) return false;
    }
  }
  return true;
}

VerifyReport verify_yes(const PolygonSet& q, const DeconstructionClaim& c,
                        const VerifyLimits& limits) {
  if (auto problem = verify::region_problem(c.solution)) {
    return report(VerifyStatus::kRefuted, "P is not a valid region: " + *problem);
  }
  // The paper's r <= eps answer P = Q: Q ⊆ offset(Q, r) ⊆ offset(Q, eps), so H <= r <= eps
  // exactly, also when r = eps leaves the quadtree no margin.
  if (c.radius <= c.tolerance && same_region(c.solution, q)) {
    return report(VerifyStatus::kVerified, "verified");
  }
  const verify::EdgeSet p_edges(c.solution, c.radius.get_d());
  const verify::EdgeSet q_edges(q, c.tolerance.get_d());
  const auto a = verify::prove_offset_within(p_edges, q_edges, c.radius, c.tolerance, limits);
  if (a.status == VerifyStatus::kRefuted) {
    return report(a.status,
                  "offset(P, r) is not within eps of Q: " + point_text(a.where) +
                      " is within r of P and farther than eps from Q",
                  a.cells);
  }
  if (a.status == VerifyStatus::kUnproven) {
    return report(a.status,
                  "could not prove offset(P, r) within eps of Q near " + point_text(a.where) +
                      " (cell budget or depth exhausted)",
                  a.cells);
  }
  const auto b = verify::prove_covered(q_edges, p_edges, c.radius + c.tolerance, limits);
  const std::size_t cells = a.cells + b.cells;
  if (b.status == VerifyStatus::kRefuted) {
    return report(b.status,
                  "Q is not within r + eps of P: " + point_text(b.where) +
                      " is in Q and farther than r + eps from P",
                  cells);
  }
  if (b.status == VerifyStatus::kUnproven) {
    return report(b.status,
                  "could not prove Q within r + eps of P near " + point_text(b.where) +
                      " (cell budget or depth exhausted)",
                  cells);
  }
  return report(VerifyStatus::kVerified, "verified", cells);
}

VerifyReport verify_no(const PolygonSet& q, const DeconstructionClaim& c,
                       const VerifyLimits& limits) {
  if (!c.no_witness) return report(VerifyStatus::kUnproven, "NO without a witness point");
  const verify::EdgeSet q_edges(q, c.tolerance.get_d());
  const verify::VPoint w = verify::vpoint(*c.no_witness);
  if (!q_edges.contains(w) && !q_edges.any_within(w, verify::threshold(Rational(0)))) {
    return report(VerifyStatus::kRefuted,
                  "the NO witness " + point_text(w.e) + " is not a point of Q");
  }
  const auto d = verify::prove_unservable(q_edges, w.e, c.radius, c.tolerance, limits);
  if (d.status != VerifyStatus::kVerified) {
    return report(VerifyStatus::kUnproven,
                  "could not prove that no valid P serves the NO witness " + point_text(w.e) +
                      ": near " + point_text(d.where) +
                      " no point within r was shown farther than eps from Q",
                  d.cells);
  }
  return report(VerifyStatus::kVerified, "verified", d.cells);
}

} // namespace

std::optional<std::string> region_problem(const PolygonSet& set) {
  return verify::region_problem(set);
}

VerifyReport verify_deconstruction(const PolygonSet& q, const DeconstructionClaim& claim,
                                   const VerifyLimits& limits) {
  check_params(claim);
  // Interval_nt<false> needs rounding towards +infinity while the proofs run.
  const CGAL::Protect_FPU_rounding<true> rounding;
  switch (claim.answer) {
    case Answer::kYes:
      return verify_yes(q, claim, limits);
    case Answer::kNo:
      return verify_no(q, claim, limits);
    case Answer::kUndecided:
      break;
  }
  return report(VerifyStatus::kVerified, "verified (UNDECIDED claims nothing)");
}

} // namespace penshape
