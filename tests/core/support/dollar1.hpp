#pragma once
// The $1 gesture logs (../shared/data/strokes/dollar1): `<Point X="130" Y="159" T="..." />`.
#include <string>
#include <vector>

#include "penshape/core/polygon_set.hpp"

namespace penshape::test {

// The points of one gesture file (pixels), in order; throws std::runtime_error if none.
std::vector<PointD> read_dollar1(const std::string& path);

} // namespace penshape::test
