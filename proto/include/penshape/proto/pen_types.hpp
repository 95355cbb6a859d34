#pragma once
// The one conversion between penshape.v1's pen messages (PenSample, TabletInfo, Stroke) and the
// core value types (penshape/types). Plain field copies with one tilt rule; what a client may send
// is validated by the daemon (daemon/proto_convert.hpp) before it reaches these.
#include "penshape/types/pen_sample.hpp"
#include "penshape/types/stroke.hpp"
#include "penshape/types/tablet_info.hpp"
#include "penshape/v1/types.pb.h"

namespace penshape::proto {

// Tilt is in degrees (types.proto, pen_sample.hpp): a pen leans at most flat on the tablet, so a
// tilt beyond ±90 is not a tilt. Larger values are clamped to ±90, which also fits PenSample's
// int16 without a narrowing that could wrap.
inline constexpr int kMaxTiltDegrees = 90;

[[nodiscard]] PenSample from_proto(const v1::PenSample& message);
[[nodiscard]] TabletInfo from_proto(const v1::TabletInfo& message); // no range checks
void to_proto(const PenSample& sample, v1::PenSample* out);
void to_proto(const TabletInfo& tablet, v1::TabletInfo* out);
void to_proto(const Stroke& stroke, v1::Stroke* out);

} // namespace penshape::proto
