#pragma once
// The Hausdorff certificate of a clean shape against the stroke (argument in recognize.hpp).
#include <span>

#include "clean_shape.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape::recognize_detail {

// Upper bound on H(stroke path, clean path), hence on H(stroke ink, clean ink) for any common pen
// radius. `extent` is the drawing's size (for the rounding margin). Sampling spacing
// h = epsilon / 6, coarsened if needed so neither side takes more than 50,000 samples.
Certificate certify(std::span<const PointD> stroke, const CleanShape& shape, double epsilon,
                    double pen_radius, double extent);

} // namespace penshape::recognize_detail
