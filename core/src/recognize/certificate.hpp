#pragma once
// The Hausdorff certificate of a clean shape against the stroke (argument in recognize.hpp).
#include "clean_shape.hpp"
#include "penshape/core/recognize.hpp"
#include "prepared_stroke.hpp"

namespace penshape::recognize_detail {

// Upper bound on H(stroke path, clean path), hence on H(stroke ink, clean ink) for any common pen
// radius. The stroke is s.points (the thinned path A'), and s.thinning (tau >= H(A, A')) is added
// to the bound; s.size is the drawing's size (for the rounding margin). Sampling spacing
// h = epsilon / 6, coarsened if needed so neither side takes more than 50,000 samples. With a
// thinned stroke the distance to it is found through a uniform segment grid; unthinned strokes
// keep the previous linear scan (the benchmark baseline).
Certificate certify(const PreparedStroke& s, const CleanShape& shape, double epsilon,
                    double pen_radius);

} // namespace penshape::recognize_detail
