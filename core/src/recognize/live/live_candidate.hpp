#pragma once
// A candidate shape kept alive while samples arrive (live_recognizer.hpp, "How candidates are
// kept"): convex polygons through the on-line annulus decision, the others by their distance
// at the fitted placement. Open shapes grow with the pen: a point beyond the end of a segment,
// of a polyline's last segment or of an arc, within epsilon of its line or circle and moving
// on in the same direction, extends the shape to it instead of killing it.
#include <cstddef>
#include <optional>
#include <span>

#include "penshape/core/annulus/online.hpp"
#include "recognize/classify/classifier.hpp"

namespace penshape::recognize_detail {

struct LiveCandidate {
  Fit fit;
  Family family;
  double rank = 0.0;
  double epsilon = 0.0;
  std::size_t generation = 0; // the refit round that made it
  std::size_t id = 0;         // unique per recognizer: tells the preview it changed
  std::size_t version = 0;    // bumped when an open shape grows
  std::optional<annulus::OnlineContainment> online; // convex polygons
  bool alive = true;
  bool grow_open = true;
  bool prospect = false; // a closed shape fitted on an open stroke (live_round.hpp)
  // The sharp-polygon rule's evidence at the fit (sharp_polygon.hpp), for the preview to weigh
  // candidates of different steps as evaluate() weighs them together (a prospect's fit measure
  // reads its one-sided distance as the bound).
  bool sharp_polygon = false;
  bool yields_to_sharp_polygon = false;
  double fit_measure = 0.0;
  // Fitted on the stroke as it is at pen-up's closure, and not grown since: finish() may reuse
  // it (prospects and grown shapes fit a partial stroke; a fresh fit ranks them better).
  [[nodiscard]] bool reusable() const { return !prospect && version == 0; }

  // A candidate from a certified plausible fit on `s`; convex polygons are seeded with the
  // stroke's fit points (`coordinate_magnitude` fixes the decision's robustness margin).
  // `grow_open`: open shapes grow with the pen (else they die at their fitted ends, the
  // previous behaviour).
  static LiveCandidate make(Scored&& scored, const PreparedStroke& s, double epsilon,
                            double coordinate_magnitude, bool grow_open);

  // Feeds one point (extending an open shape when it continues it); false once the candidate
  // can no longer fit.
  bool accept(PointD p);
  // Feeds points in order, stopping at the first that kills it.
  bool accept_all(std::span<const PointD> points);

  // The fit moved to the on-line decision's verified translation (when it has one).
  [[nodiscard]] Fit placed() const;
  // The translation placed() applies (zero without a verified one).
  [[nodiscard]] PointD shift() const;
};

} // namespace penshape::recognize_detail
