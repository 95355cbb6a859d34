#pragma once
// On-line containment decision under translation (paper Section 4): points arrive one at a time;
// after each point the answer says whether a translate of the delta-annulus of a convex template
// contains all points so far. NO is final (more points cannot help) and is given as soon as it
// holds. Each point keeps the placements with it on the inner/outer boundary that contain all
// points applied to it; a point whose set empties is discarded and queued (pruning, Sec. 4.3), and
// queued points are applied lazily to the surviving sets before a YES is given. A YES keeps its
// witness placement; while new points fall inside it the answer costs one exact check, otherwise
// a new witness is searched over all points (anchored sweeps, narrowed annulus, exact check).
// Cost per point O(h m^2) for the structures (h = active structures, Sec. 4.3), plus the witness
// search when the witness breaks. Convex templates (kRound or kLinearized) and simple templates
// (kRound only; the delta-wide region of Section 5: each point keeps one set per offset piece,
// 3m pieces, so a point costs O(h m^2) as for convex templates, with the larger constant).
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "penshape/core/annulus/annulus_template.hpp"

namespace penshape::annulus {

class OnlineContainment {
 public:
  // Throws InvalidInput for a simple (non-convex) template with kLinearized, or a bad delta. The
  // robustness margin is fixed from the template, delta and `coordinate_magnitude` (the expected
  // largest |x|, |y| of points).
  OnlineContainment(const TemplatePolygon& p, OuterOffset outer, double delta,
                    double coordinate_magnitude = 0.0, const Limits& limits = {});
  ~OnlineContainment();
  OnlineContainment(OnlineContainment&&) noexcept;
  OnlineContainment& operator=(OnlineContainment&&) noexcept;

  // Adds a point (InvalidInput if not finite) and returns the answer for all points so far:
  // kYes with an exactly verified placement(), kNo (final), or kUndecided (within the margin).
  Answer add(PointD q);
  // Adds points in order (InvalidInput, adding none, if one is not finite) and returns the
  // answer for all points so far, with the same guarantees as add(): NO exactly when no
  // translate of the (margin-widened) annulus contains them all, YES with a verified
  // placement. The witness is looked for once, after the last point (a batch pays the
  // structures, not a search per point). An empty batch returns answer().
  Answer add_all(std::span<const PointD> points);

  [[nodiscard]] Answer answer() const;
  [[nodiscard]] const Placement& placement() const; // valid when answer() == kYes
  [[nodiscard]] std::size_t points() const;
  [[nodiscard]] std::size_t active_structures() const;     // h_i of the paper
  [[nodiscard]] std::size_t max_active_structures() const; // h

 private:
  struct State;
  std::unique_ptr<State> state_;
};

} // namespace penshape::annulus
