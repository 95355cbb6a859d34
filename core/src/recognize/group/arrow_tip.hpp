#pragma once
// An arrow's tip is an end (group_recognize.hpp, "Grouping"): no stroke drawn near it leaves the
// tip forward, along the shaft. A body that goes on past the shoulders of a stick figure, or a leg
// that leaves the hip where arms meet it, makes an "arrow" of body and arms; an arrow's tip meets
// a box or a circle across its line, never along it.
#include <span>
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::recognize_detail {

// Why a stroke of `others` (paths, each with >= 1 point) continues the arrow `r` forward from a
// tip (empty when none does, and for any other class): it comes within `join` of the tip and, on
// one side of that point, leaves the tip's `join`-disk and reaches 2 `join` from the tip without
// leaving the cone of half-angle GroupRules::max_continuation_angle around the shaft's direction.
std::string tip_continued(const Recognition& r, std::span<const std::vector<PointD>> others,
                          double join);

} // namespace penshape::recognize_detail
