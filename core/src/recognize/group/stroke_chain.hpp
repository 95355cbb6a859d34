#pragma once
// Several strokes read as one path (group_recognize.hpp, "Recognizing a union"): the order and
// directions that make the pen-up jumps between them shortest, and how far apart two strokes are.
#include <vector>

#include "recognize/fitting/geometry.hpp"

namespace penshape::recognize_detail {

// The pieces joined end to start in the order and directions that minimise the summed jumps
// (every order and direction for up to 6 pieces, greedily beyond).
std::vector<PointD> chain_pieces(const std::vector<std::vector<PointD>>& pieces);

// The pen-up jumps of chain_pieces()'s order, in that order (one fewer than the pieces).
std::vector<double> chain_jumps(const std::vector<std::vector<PointD>>& pieces);

// The smallest distance between two polylines (0 when they cross).
double polyline_gap(const std::vector<PointD>& a, const std::vector<PointD>& b);

} // namespace penshape::recognize_detail
