#pragma once
// The certificate of a clean shape against SEVERAL strokes: the Hausdorff bound of recognize.hpp
// with A the union of the strokes' paths (group_recognize.hpp, "Recognizing a union").
#include <vector>

#include "penshape/core/recognize.hpp"
#include "recognize/fitting/clean_shape.hpp"

namespace penshape::recognize_detail {

struct UnionStroke {
  // Each stroke's thinned path A_i' (H(A_i, A_i') <= thinning); the jumps between strokes are
  // not part of the union.
  std::vector<std::vector<PointD>> pieces;
  double thinning = 0.0; // tau >= H(union of A_i, union of A_i') (one tau for every piece)
  double size = 0.0;     // bounding-box diagonal of the union
};

// `paths` are the strokes' deduplicated paths (each with >= 2 distinct points); tau as
// thinning_tolerance() gives it.
UnionStroke prepare_union(const std::vector<std::vector<PointD>>& paths, double tau);

// Upper bound on H(union of paths, clean path) (hence on the inks' distance for one pen radius):
// every piece sampled with spacing <= h against the shape, the shape sampled with spacing <= h
// against the nearest piece, each distance an interval upper bound (certified_distance.hpp) plus
// the half step actually taken, + tau, exactly as certify() does for one stroke.
Certificate certify_union(const UnionStroke& u, const CleanShape& shape, double epsilon,
                          double pen_radius);

// Distance from p to the union of the pieces (brute force over their segments).
double union_distance(const UnionStroke& u, PointD p);

} // namespace penshape::recognize_detail
