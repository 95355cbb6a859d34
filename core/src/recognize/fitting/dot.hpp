#pragma once
// Dots: a stroke whose samples all sit at one position (a full stop, the dot of an i, a tap).
// It is a shape of its own (ShapeClass::kDot), never an error.
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::recognize_detail {

// True when every sample has the position of the first (and there is at least one sample).
bool is_dot(const std::vector<StrokePoint>& samples);

// The recognition of a dot: the clean shape is the point itself, so the path certificate's bound
// is exactly 0 (H(path, clean path) = 0) and it certifies against any epsilon >= 0.
Recognition dot_recognition(const std::vector<StrokePoint>& samples, const ToleranceChoice& tol);

} // namespace penshape::recognize_detail
