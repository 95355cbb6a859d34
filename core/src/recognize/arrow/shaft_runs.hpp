#pragma once
// Where an arrow drawn with a curved or bent shaft may have its tip, and the strokes' runs that
// may be its shaft (fit_arrow.cpp seeks the head against such a shaft's own end: its barbs can
// both lie on one side of the chord tail -> tip, and the shaft itself passes for a barb there).
#include <utility>
#include <vector>

#include "recognize/certify/union_certificate.hpp"

namespace penshape::recognize_detail {

// The places where a stroke ends or turns back (by more than kTipTurn between its points
// epsilon / 2 before and after: a shaft arriving at its tip and leaving along a barb, a head's V,
// a barb's end), each with its turn (ends as turning fully back), sharpest first.
std::vector<std::pair<double, PointD>> turn_places(const UnionStroke& u, double epsilon);

// Where a drawing may have its tip: one point per turn place, the sharpest first (places within
// epsilon of a sharper one are dropped).
std::vector<PointD> tip_candidates(const std::vector<std::pair<double, PointD>>& turns,
                                   double epsilon);

// A stroke's run taken as a shaft: its points as drawn from the tail to the one nearest the tip,
// the tip, and the point the direction back along the shaft from the tip is taken to (its first
// point kShaftEndReach of it away from the tip: near, since a curved shaft's chord to it is off
// its tangent at the tip by half its turn on the way).
struct ShaftRun {
  std::vector<PointD> run;
  PointD tip;
  PointD back_point;
};

// The runs that may be the shaft of an arrow with its tip at `tip`: each stroke passing within
// epsilon of the tip followed from its point nearest the tip both ways, and also from where it
// last leaves the tip (a barb drawn out and back from the tip is not the shaft). Only runs longer
// than 2 epsilon whose end leaves their chord by kMinShaftEndTurn or more (a straight shaft's
// head is found against the chord).
std::vector<ShaftRun> shaft_runs(const UnionStroke& u, PointD tip, double epsilon);

// Up to two bends of a shaft drawn along `run` (tail to tip), Douglas-Peucker: the run's point
// farthest from the chord when farther than epsilon / 2, then the farther of the two halves'.
std::vector<PointD> run_bends(const std::vector<PointD>& run, double epsilon);

// The signed bulge of the arc through a run's ends that passes its middle: the middle's offset
// to the left of the chord.
double run_bulge(const std::vector<PointD>& run);

} // namespace penshape::recognize_detail
