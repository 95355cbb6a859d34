#pragma once
// A refit round of the bounded live policy (live_recognizer.hpp, "Refit policy"): the families
// that apply to a snapshot of the stroke, fitted and certified one per step so that no single
// add() pays for all of them.
//
// An open stroke that has gone most of the way round (it is at least 1.5 times as long as its
// size and its end is within 0.75 times its size of its start) also tries the closed families
// as prospects: a closed shape the stroke can still become. A prospect needs only the
// one-sided test that matters before pen-up, every point of the fitted path within epsilon of
// the shape (estimated on the path's points, not certified), and the stroke must not trace the
// shape over (at most 1.6 times its length, as for snaps); it ranks like a snap with that
// one-sided distance in place of the certified bound.
#include <cstddef>
#include <optional>
#include <vector>

#include "recognize/classify/classifier.hpp"

namespace penshape::recognize_detail {

class RefitRound {
 public:
  // `stroke` is the (thinned, capped) path at the start of the round; `kept_at_start` the
  // number of kept points it covers (later kept points are fed to the round's candidates).
  RefitRound(PreparedStroke stroke, const ToleranceChoice& tolerance, std::size_t kept_at_start,
             const RecognizerConfig& config);

  // Which families a round on this stroke tries: 0 open, 1 open with closed prospects,
  // 2 closed. A change of stage starts a new round.
  static int stage(const PreparedStroke& stroke, double epsilon);

  [[nodiscard]] bool done() const { return next_ >= steps_.size() && pending_.empty(); }
  // Fits and evaluates the next family (fits made together are evaluated one per step);
  // returns its certified plausible fits (snaps).
  std::vector<Scored> step();

  [[nodiscard]] const PreparedStroke& stroke() const { return stroke_; }
  [[nodiscard]] double epsilon() const { return tolerance_.epsilon; }
  [[nodiscard]] bool closed() const { return closed_; }
  [[nodiscard]] int stage() const { return stage_; }
  [[nodiscard]] std::size_t kept_at_start() const { return kept_at_start_; }
  [[nodiscard]] bool found_snap() const { return found_snap_; }
  // Whether the last step() fitted a closed family as a prospect on an open stroke.
  [[nodiscard]] bool last_step_prospective() const { return last_prospective_; }

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
    kPolygon, // polygons of n corners: the corner search's and the sharp turns' (sharp_polygon.hpp)
    kEllipse,
  };
  struct Step {
    Kind kind = Kind::kSegment;
    std::size_t n = 0;        // polyline vertices / (regular) polygon corners
    bool prospective = false; // a closed family tried on an open stroke
  };
  std::vector<Scored> prospects(std::vector<Fit> fits) const;
  std::vector<Scored> finish_step(std::vector<Fit> fits, bool prospective);

  PreparedStroke stroke_;
  ToleranceChoice tolerance_;
  std::size_t kept_at_start_ = 0;
  RecognizerConfig config_;
  bool closed_ = false;
  int stage_ = 0;
  bool found_snap_ = false;
  bool last_prospective_ = false;
  std::vector<Step> steps_;
  std::size_t next_ = 0;
  std::optional<Fit> quadrilateral_; // shared by the quadrilateral and rectangle steps
  std::optional<Fit> circle_;        // shared by the circle and regular polygon steps
  // Fits made together (rectangle, square and diamond; polygon_fits' few), one per step.
  std::vector<Fit> pending_;
};

} // namespace penshape::recognize_detail
