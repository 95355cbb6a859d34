#pragma once
// A refit round of the bounded live policy (live_recognizer.hpp, "Refit policy"): the families
// that apply to a snapshot of the stroke, fitted and certified one per step so that no single
// add() pays for all of them.
#include <cstddef>
#include <optional>
#include <vector>

#include "classifier.hpp"

namespace penshape::recognize_detail {

class RefitRound {
 public:
  // `stroke` is the (thinned, capped) path at the start of the round; `kept_at_start` the
  // number of kept points it covers (later kept points are fed to the round's candidates).
  RefitRound(PreparedStroke stroke, const ToleranceChoice& tolerance, std::size_t kept_at_start,
             const RecognizerConfig& config);

  [[nodiscard]] bool done() const { return next_ >= steps_.size(); }
  // Fits and evaluates the next family; returns its certified plausible fits (snaps).
  std::vector<Scored> step();

  [[nodiscard]] const PreparedStroke& stroke() const { return stroke_; }
  [[nodiscard]] double epsilon() const { return tolerance_.epsilon; }
  [[nodiscard]] bool closed() const { return closed_; }
  [[nodiscard]] std::size_t kept_at_start() const { return kept_at_start_; }
  [[nodiscard]] bool found_snap() const { return found_snap_; }
  // The families this round fits (confirmed or dropped when it ends).
  [[nodiscard]] std::vector<Family> families() const;

 private:
  enum class Kind {
    kSegment,
    kPolyline,
    kArc,
    kCircle,
    kTriangle,
    kQuadrilateral,
    kRectangles, // rectangle, square and diamond from the quadrilateral
    kRegularPolygon,
    kEllipse,
  };
  struct Step {
    Kind kind;
    std::size_t n = 0; // polyline vertices / regular polygon sides
  };

  PreparedStroke stroke_;
  ToleranceChoice tolerance_;
  std::size_t kept_at_start_ = 0;
  RecognizerConfig config_;
  bool closed_ = false;
  bool found_snap_ = false;
  std::vector<Step> steps_;
  std::size_t next_ = 0;
  std::optional<Fit> quadrilateral_; // shared by the quadrilateral and rectangle steps
  std::optional<Fit> circle_;        // shared by the circle and regular polygon steps
};

} // namespace penshape::recognize_detail
