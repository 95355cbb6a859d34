#pragma once
// Whether a closed stroke turns at a polygon's corners as a drawn corner does, or passes them as
// a curve does: the evidence that tells a hexagon from a circle when both lie within tolerance.
#include <optional>
#include <vector>

#include "penshape/core/point_arithmetic.hpp"
#include "recognize/fitting/path_turn.hpp"

namespace penshape::recognize_detail {

// The least share of the polygon's turn that the stroke makes at a corner: at each corner v
// (turn theta), the stroke's turn between chords `window` times the shorter side beside v either
// way from its point nearest v, over theta. A sharp corner gives about 1; a circle through the
// corners gives about `window` (the arc between the chords). Corners nearer than that to the
// stroke's ends (where a closed stroke starts and stops) are not measured; 0 when none is.
double least_corner_share(const std::vector<PointD>& stroke, const std::vector<PointD>& corners,
                          double window);
// The stroke's turn (radians) at the closed polygon's corner k, between chords `window` times the
// shorter side beside it either way from the stroke's point nearest it; nothing near an end.
std::optional<double> stroke_turn_at_corner(const ArcLengthPath& stroke,
                                            const std::vector<PointD>& corners, std::size_t k,
                                            double window);
// Each measured corner's share, in the corners' order (corners not measured are left out).
std::vector<double> corner_shares(const std::vector<PointD>& stroke,
                                  const std::vector<PointD>& corners, double window);
// The mean share over the measured corners, or nothing when none is measured.
std::optional<double> mean_corner_share(const std::vector<PointD>& stroke,
                                        const std::vector<PointD>& corners, double window);
// The least share, or nothing when no corner could be measured (no evidence either way).
std::optional<double> measured_corner_share(const std::vector<PointD>& stroke,
                                            const std::vector<PointD>& corners, double window);

} // namespace penshape::recognize_detail
