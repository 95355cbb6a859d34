#pragma once
// The certificate of a replacement for the ink actually drawn and actually written, when the pen
// width varies (Xournal++ pressure, calligraphy). The recognizer certifies the clean path C swept
// by one pen of radius r (the median): method "ink" bounds H(C ⊕ r, Q) with Q the ink as drawn,
// its own widths included; method "path" bounds H(C, P) for the drawn path P, hence H(C ⊕ r,
// P ⊕ r), which is the drawn ink only when its width is r throughout.
// The lemma: a set swept along a path with radii ρ (constant per piece, or interpolated between
// sample radii) lies within max |ρ - r| of the same path swept with r, both ways: a point in a
// disk of radius ρ about a path point is within max(ρ - r, 0) of that point's disk of radius r,
// and the other way round. So, by the triangle inequality,
//   - the written ink W (a pressure stroke keeps its profile: segment i of C drawn with its own
//     radius ρ_i, taken from the stroke's radii, xopp_strokes.hpp) is within max |ρ - r| of
//     C ⊕ r, over the written radii;
//   - for method "path", P ⊕ r is within max |ρ - r| of Q, over the drawn radii of every stroke
//     of the group;
// and H(W, Q) <= bound + both terms (each only where it applies), rounded up. That is the
// certificate reported; when it exceeds the tolerance the replacement is not certified and the
// strokes stay as drawn.
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::snap {

// Widens r's certificate from the median pen to the written radii `written` and, for a path
// certificate, the drawn radii `drawn` (every radius > 0). Returns whether it still holds
// (bound <= epsilon); when not, r is marked uncertified.
bool certify_width_profile(Recognition& r, const std::vector<double>& written,
                           const std::vector<double>& drawn);

} // namespace penshape::snap
