#pragma once
// The Hausdorff certificate of a clean shape against the stroke (argument in recognize.hpp).
#include "penshape/core/recognize.hpp"
#include "recognize/fitting/clean_shape.hpp"
#include "recognize/fitting/prepared_stroke.hpp"

namespace penshape::recognize_detail {

// Upper bound on H(stroke path, clean path), hence on H(stroke ink, clean ink) for any common pen
// radius. The stroke is s.points (the thinned path A'), and s.thinning (tau >= H(A, A')) is added
// to the bound. Sampling spacing h = epsilon / 6, coarsened if needed so neither side takes more
// than 50,000 samples. Doubles propose the nearest part of the other side; each distance in the
// bound is an interval upper bound with directed rounding, and the half steps are added rounded
// up (certified_distance.hpp): no margin. With a thinned stroke the nearest stroke segment is
// proposed by a uniform segment grid; unthinned strokes keep the previous linear scan (the
// benchmark baseline).
Certificate certify(const PreparedStroke& s, const CleanShape& shape, double epsilon,
                    double pen_radius);

} // namespace penshape::recognize_detail
