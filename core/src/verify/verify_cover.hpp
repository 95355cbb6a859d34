#pragma once
// The verifier's three coverage proofs, each a quadtree of exact cell tests (verify.hpp says
// what they prove). Internal to core/src/verify.
#include <cstddef>

#include "penshape/core/verify.hpp"
#include "verify/verify_edges.hpp"

namespace penshape::verify {

struct CoverOutcome {
  VerifyStatus status = VerifyStatus::kVerified;
  ExactPoint where; // the counterexample (refuted) or the cell left open (unproven)
  std::size_t cells = 0;
};

// (A) offset(P, r) ⊆ offset(Q, eps).
CoverOutcome prove_offset_within(const EdgeSet& p, const EdgeSet& q, const Rational& r,
                                 const Rational& eps, const VerifyLimits& limits);
// (B) Q ⊆ offset(P, reach).
CoverOutcome prove_covered(const EdgeSet& q, const EdgeSet& p, const Rational& reach,
                           const VerifyLimits& limits);
// NO: every y ∈ D_{r+eps}(w) has a z with |z - y| < r and d(z, Q) > eps (w ∈ Q is checked by
// the caller).
CoverOutcome prove_unservable(const EdgeSet& q, const ExactPoint& w, const Rational& r,
                              const Rational& eps, const VerifyLimits& limits);

} // namespace penshape::verify
