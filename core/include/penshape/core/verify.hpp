#pragma once
// An independent checker for deconstruction answers (`penshape verify`). It shares no geometry
// code with the engines: its own predicates (interval arithmetic with directed rounding, exact
// rationals when an interval cannot decide) and its own proofs, so a mistake in an engine's
// certificate does not repeat itself here.
//
// YES (P given):  P is a valid region (simple rings that do not meet, holes inside their outer
//   ring, polygons apart; a zero-area ring is an open polyline, as simplified solutions use),
//   and H(offset(P, r), Q) <= eps, proven as the two inclusions of Proposition 3
//   (deconstructing-approximate-offsets): (A) offset(P, r) ⊆ offset(Q, eps) and
//   (B) Q ⊆ offset(P, r + eps). Each is proven on a quadtree whose cells are settled by a
//   Lipschitz bound at the cell's centre with the cell's half-diagonal rounded up to a rational:
//   every comparison is exact, the offsets' arcs are the true circles (no polygonal disks).
// NO (witness q given): q ∈ Q and every point y of the disk D_{r+eps}(q) sees, within r, a point
//   z with d(z, Q) > eps. Then no y there is in Π = inset(offset(Q, eps), r), every valid P lies
//   in Π (inclusion (A)), so offset(P, r + eps) misses q ∈ Q and (B) fails for every P.
// UNDECIDED claims nothing and is accepted.
//
// A failure is either refuted (an exact counterexample point, named in the message) or unproven
// (the cell budget ran out or cells became too small, near the named point): both reject.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_set.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape {

struct DeconstructionClaim {
  Answer answer = Answer::kUndecided;
  Rational radius;                      // r > 0
  Rational tolerance;                   // eps > 0
  Rational precision;                   // delta, 0 < delta < eps
  PolygonSet solution;                  // with YES
  std::optional<ExactPoint> no_witness; // with NO
};

enum class VerifyStatus { kVerified, kRefuted, kUnproven };
const char* to_string(VerifyStatus s); // "verified", "refuted", "unproven"

struct VerifyReport {
  VerifyStatus status = VerifyStatus::kUnproven;
  std::string message;   // "verified" or what fails, with the point where it fails
  std::size_t cells = 0; // quadtree cells examined
};

struct VerifyLimits {
  std::size_t max_cells = 2'000'000; // per inclusion
  int max_depth = 40;                // cells halve at most this often below the start square
};

// The verifier's own validity check of a region (used for P, and by the CLI for Q): nullopt when
// valid, else what is wrong and where. See verify_valid.hpp for the rules.
std::optional<std::string> region_problem(const PolygonSet& set);

// Q must be a valid region (validate with the caller's reader; an invalid claim is reported,
// not thrown). Throws InvalidInput for parameters out of range (r, eps, delta).
VerifyReport verify_deconstruction(const PolygonSet& q, const DeconstructionClaim& claim,
                                   const VerifyLimits& limits = {});

} // namespace penshape

// ---- Recognition answers (penshape verify with a stroke file) ----
// A recognition claims H(C ⊕ D_r, A ⊕ D_r) <= bound <= eps for the clean shape C its class and
// params describe (recognize.hpp, group_recognize.hpp; a curved arrow shaft is the 12 chords
// that were certified), the union A of the strokes' paths, the pen radius r and the bound its
// certificate states. A bound above eps is refuted outright. Otherwise the verifier proves the
// stronger H(C, A) <= bound (a common pen disk never increases the Hausdorff distance): both
// directions by subdividing each side's segments until d(midpoint, other side) + half the piece
// <= bound, every comparison an interval evaluation with directed rounding (an inconclusive one
// subdivides further). Curves are replaced by chord polylines with a derived deviation sigma
// (verify/verify_shape.hpp), so the budget is bound - sigma. Refuted: a point of one path
// farther than bound + r + sigma from the other, which is a point of one ink farther than bound
// from the other ink. Unproven: the paths are not within the bound there; an answer certified on
// inks (method "ink", variable radius) may be correct and still end here, as the check is on
// paths. Without a bound the claim is H <= eps. Freeform claims nothing and is accepted.
namespace penshape {

struct RecognitionClaim {
  ShapeClass shape = ShapeClass::kFreeform;
  ShapeParams params;
  double epsilon = 0.0;
  double pen_radius = 0.0;
  std::optional<double> bound = std::nullopt; // the certificate's bound; absent: the claim is eps
};

// `strokes`: each stroke's positions in drawing order (>= 1 each). Throws InvalidInput for
// parameters out of range, missing or non-finite shape parameters, or empty strokes.
VerifyReport verify_recognition(const std::vector<std::vector<PointD>>& strokes,
                                const RecognitionClaim& claim, const VerifyLimits& limits = {});

} // namespace penshape
