#pragma once
// The verifier's own picture of a recognized clean shape (penshape verify, recognition answers):
// polylines with exact (double) vertices and a deviation sigma, rounded up, with
// H(true clean shape, polylines) <= sigma. Straight shapes (bent arrow shafts included: the
// polyline through ShapeParams::shaft_bends) are exact (sigma = 0); a curved arrow shaft is what
// the recognizer certified, the 12 chords of its arc at equal angle steps (their vertices
// enclosed on the true circle, sigma from the boxes and the angles' error); circles,
// ellipses and arcs are chord polylines whose sigma is derived, not chosen:
// for a curve P(t) with |P''| <= M sampled at parameters t_k with gaps <= dt, the chord through
// P(t_k), P(t_k+1) stays within M dt^2 / 8 of the arc between them (and the arc of it), pointwise
// at the same t; each vertex V_k is the midpoint of an interval box holding P(t_k), so it adds the
// box's half-diagonal. sin and cos come from the C library and are widened by two ulps each side
// (glibc documents at most 1 ulp for them on x86-64 and aarch64). Written apart from the
// recognizer: it shares none of its code.
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::verify {

struct ShapeChains {
  std::vector<std::vector<PointD>> chains; // each with >= 1 vertex
  double deviation = 0.0;                  // sigma, an upper bound
};

// The clean shape of (shape, params) with sigma <= about `target` for curves. Throws InvalidInput
// for freeform, missing or non-finite parameters, or the wrong vertex count.
ShapeChains shape_chains(ShapeClass shape, const ShapeParams& params, double target);

} // namespace penshape::verify
