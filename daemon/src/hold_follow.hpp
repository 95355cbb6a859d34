#pragma once
// Hold to snap: where the held shape goes as the pen moves on after the hold (live.proto's
// HoldSnap). Pure geometry on display doubles: the moved shape is the user's explicit edit of a
// certified one, so nothing here decides a certificate.
#include "penshape/v1/shape.pb.h"

namespace penshape::daemon {

struct PointMm {
  double x = 0;
  double y = 0;
};

// The held shape moved by the pen going from `hold` (where it held still) to `tip`: the end of a
// segment and the corner of a rectangle nearest the hold move with the tip (the rectangle keeps its
// directions and opposite corner); a circle's radius grows by the tip's gain in distance from the
// center; any other shape is scaled and rotated so that `hold` goes to `tip`, about its first
// point (first vertex, arrow tail, arc start, ellipse center; a polygon held nearer its first
// vertex than its center, as a closed stroke ends, turns about its vertices' mean instead).
// The certificate is kept, its scope "drawn_part+user_edit".
v1::Shape follow_shape(const v1::Shape& held, PointMm hold, PointMm tip);

} // namespace penshape::daemon
