#pragma once
// The annulus step for polygon snaps: the winner's polygon, taken as a template, is re-placed by
// the minimum-width annulus under translation (penshape/core/annulus/translation.hpp) over the
// stroke's fit points, which minimises the largest distance from the stroke to the polygon for
// that shape. The moved polygon replaces the winner only when its own certificate is better.
#include "recognize/classify/classifier.hpp"

namespace penshape::recognize_detail {

// For convex polygon classes (triangle, quadrilateral, rectangle, square, diamond, regular
// polygon); other candidates are left as they are. Returns whether the placement improved.
bool polish_with_annulus(const PreparedStroke& s, Scored& winner, const RecognizerConfig& config);

} // namespace penshape::recognize_detail
