#pragma once
// Offset deconstruction (../shared/papers/deconstructing-approximate-offsets.txt, Sections 2-3):
// given a polygonal region Q, a radius r and a tolerance eps, is there a polygonal region P
// whose r-offset is within Hausdorff distance eps of Q? APPROXDECIDE answers with a working
// precision delta < eps:
//   YES       certified: the returned P satisfies P ⊆ Π = inset(offset(Q, eps), r) and
//             Q ⊆ offset(P, r + eps), hence H(offset(P, r), Q) <= eps (Proposition 3).
//   NO        certified: no polygonal P exists (the exterior approximation excludes part of Q).
//   UNDECIDED delta is too coarse to tell; a smaller delta decides (Theorems 11, 13).
// With r <= eps the answer is YES with P = Q, as in the paper.
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "penshape/core/base.hpp"
#include "penshape/core/polygon_set.hpp"

namespace penshape {

enum class Answer { kYes, kNo, kUndecided };
enum class EngineKind { kFast, kReference };

const char* to_string(Answer a);     // "YES", "NO", "UNDECIDED"
const char* to_string(EngineKind e); // "fast", "reference"

// CancelHook, Cancelled and InvalidInput are in penshape/core/base.hpp (included above).

struct DeconstructParams {
  Rational radius;    // r > 0
  Rational tolerance; // eps > 0
  Rational precision; // delta, 0 < delta < eps
  EngineKind engine = EngineKind::kFast;
};

// Explicit limits; exceeding one is InvalidInput whose message states the limit.
struct DeconstructLimits {
  std::size_t max_input_vertices = 200'000;
  // Vertices of the largest disk approximation D̄_{a,b} (it grows like sqrt(b / (b - a))).
  std::size_t max_disk_vertices = 4'096;
};

struct DeconstructResult {
  Answer answer = Answer::kUndecided;
  EngineKind engine = EngineKind::kFast;
  DeconstructParams params;
  // With YES: the solution P (P ⊆ Π̂ ⊆ Π and Q ⊆ offset(P, r + eps)). Empty otherwise.
  PolygonSet solution;
  // With YES: an upper bound on H(offset(P, r), Q) that the certificate proves (<= eps).
  Rational hausdorff_bound;
  // With NO: a point q of Q that no solution can serve, D_{r+eps}(q) ∩ Π = ∅ (Corollary 6): every
  // valid P lies in Π, so offset(P, r + eps) misses q. `penshape verify` re-checks it.
  std::optional<ExactPoint> no_witness;
  std::size_t disk_vertices = 0;       // vertices of the largest disk approximation used
  std::chrono::nanoseconds elapsed{0}; // whole call, validation included
};

// Validates a region on its own: at least one polygon, at most max_vertices vertices, every ring
// with >= 3 vertices, no repeated consecutive vertex, non-zero area, no two edges touching or
// crossing (within a ring or between rings), every hole inside its outer ring and outside the
// other holes, polygons pairwise disjoint (one may sit inside another's hole). Orientation is not
// checked (normalize_orientation fixes it). Throws InvalidInput naming polygon, ring and vertex.
// Cost: the touching/crossing test is a Shamos–Hoey sweep, O(n log n) exact predicates whatever
// the shape (combs included); the nesting test places one vertex of each ring against the rings
// it may lie in, O(n·(h + p)) for h holes and p polygons (a bounding box rejects most). cancel is
// checked every 256 event points of the sweep (throws Cancelled).
void validate_region(const PolygonSet& q, std::size_t max_vertices = 200'000,
                     const CancelHook& cancel = {});

// Validates Q (validate_region with limits.max_input_vertices) and the parameters: r, eps,
// delta > 0 and delta < eps (rationals are always finite; text and double inputs are checked
// where they are parsed), and with r > eps the largest disk the engines build,
// D̄_{r+eps, r+eps+delta}, within limits.max_disk_vertices (every other disk is smaller). Throws
// InvalidInput naming the problem and the bound.
void validate_deconstruct_input(const PolygonSet& q, const DeconstructParams& params,
                                const DeconstructLimits& limits = {},
                                const CancelHook& cancel = {});
// The parameters' part of validate_deconstruct_input alone (for a ValidatedRegion).
void validate_deconstruct_params(const DeconstructParams& params,
                                 const DeconstructLimits& limits = {});

// APPROXDECIDE(Q, r, eps, delta) with the chosen engine: validates (InvalidInput), answers
// r <= eps with YES and P = Q, else dispatches to the engine. Q may have any ring orientation.
// cancel is checked during validation and between the engine's steps (Cancelled).
DeconstructResult deconstruct(const PolygonSet& q, const DeconstructParams& params,
                              const CancelHook& cancel = {}, const DeconstructLimits& limits = {});

} // namespace penshape
