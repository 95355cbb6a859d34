#pragma once
// Certified tidy-up of a recognized shape (group_recognize.hpp, "Tidy-up"): each constraint is
// proposed, certified on the same strokes, and kept only when the certificate still holds.
#include <numbers>
#include <string>
#include <vector>

#include "penshape/core/group_recognize.hpp"
#include "union_certificate.hpp"

namespace penshape::recognize_detail {

// A corner within this of a right angle is drawn as one: the tidy-up makes it right, and a
// rhombus whose angles are this close to 90 degrees is a square, not a diamond (classifier).
inline constexpr double kRightAngleSlack = 10.0 * std::numbers::pi / 180.0;

// Applies the enabled constraints to `r` (a snap; freeform is left alone) in the documented
// order and returns the names of those applied. `neighbours` are recent shapes (connection,
// parallel); `u` the strokes `r` was recognized from.
// With `ink` (one stroke recognized on its ink polygon), a proposal must also certify on the
// ink, and the ink certificate is kept.
std::vector<std::string> tidy_up(Recognition& r, const UnionStroke& u, const TidyConfig& config,
                                 const std::vector<const Recognition*>& neighbours,
                                 const InkPolygon* ink = nullptr);

} // namespace penshape::recognize_detail
