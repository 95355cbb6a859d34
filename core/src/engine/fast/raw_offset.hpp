#pragma once
// The raw outward offset path of integer rings with round joins, whose positive-winding region
// Clipper's union turns into the offset (clipper_stage.cpp), and the pruning of the spokes of
// its reflex corners where they provably change nothing (README.md, "Reflex spokes"). Internal
// to the fast engine: its results are candidates, never trusted by a certificate.
#include <clipper.hpp>

#include "clipper_stage.hpp" // Spokes
#include "int_geometry.hpp"

namespace penshape::fast {

// For each ring (region on its left, nonzero winding), the path of round joins with ceil'd step
// counts (chords exactly as deep as `arc_tolerance`) joined by the offset edges, and at each
// other corner a spoke through the vertex: v + delta n0 -> v -> v + delta n1, except the spokes
// `spokes` drops.
ClipperLib::Paths raw_outward(const IRings& rings, double delta, double arc_tolerance,
                              Spokes spokes);

// The spoke at v (previous vertex u, next w) may be dropped: with s = the last path point of u's
// join, a = v + delta n0 and b = v + delta n1 (as rounded on the path) and e = the first point
// of w's join, the quadrilaterals R0 = (u, s, a, v) and R1 = (v, b, e, w) (the parts the two
// edges add, as the path draws them) are strictly convex and counterclockwise, and b lies in
// R0 and a in R1 (exact integer tests). Then the triangle (v, a, b) lies in both.
bool spoke_is_covered(IPt u, IPt s, IPt a, IPt v, IPt b, IPt e, IPt w);

} // namespace penshape::fast
