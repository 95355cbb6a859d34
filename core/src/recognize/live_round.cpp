// One-family-per-step refit rounds (see live_round.hpp). The families and the fitters are the
// ones fit_all() uses, so a round proposes what a full refit would, only spread over calls.
#include "live_round.hpp"

#include <cmath>

namespace penshape::recognize_detail {

RefitRound::RefitRound(PreparedStroke stroke, const ToleranceChoice& tolerance,
                       std::size_t kept_at_start, const RecognizerConfig& config)
    : stroke_(std::move(stroke)),
      tolerance_(tolerance),
      kept_at_start_(kept_at_start),
      config_(config),
      closed_(is_closed(stroke_, tolerance.epsilon)) {
  // Cheap, common families first: the preview appears sooner.
  if (!closed_) {
    steps_.push_back({Kind::kSegment});
    steps_.push_back({Kind::kArc});
    for (std::size_t k = 2; k <= config.max_polyline_segments; ++k) {
      steps_.push_back({Kind::kPolyline, k + 1});
    }
    return;
  }
  steps_.push_back({Kind::kCircle});
  steps_.push_back({Kind::kTriangle});
  steps_.push_back({Kind::kQuadrilateral});
  steps_.push_back({Kind::kRectangles});
  steps_.push_back({Kind::kEllipse});
  for (const std::size_t n : {std::size_t{5}, std::size_t{6}, std::size_t{8}}) {
    steps_.push_back({Kind::kRegularPolygon, n});
  }
}

std::vector<Family> RefitRound::families() const {
  std::vector<Family> out;
  for (const Step& s : steps_) {
    switch (s.kind) {
      case Kind::kSegment:
        out.push_back({ShapeClass::kSegment, 0});
        break;
      case Kind::kPolyline:
        out.push_back({ShapeClass::kPolyline, s.n});
        break;
      case Kind::kArc:
        out.push_back({ShapeClass::kArc, 0});
        break;
      case Kind::kCircle:
        out.push_back({ShapeClass::kCircle, 0});
        break;
      case Kind::kTriangle:
        out.push_back({ShapeClass::kTriangle, 0});
        break;
      case Kind::kQuadrilateral:
        out.push_back({ShapeClass::kQuadrilateral, 0});
        break;
      case Kind::kRectangles:
        out.push_back({ShapeClass::kRectangle, 0});
        out.push_back({ShapeClass::kSquare, 0});
        out.push_back({ShapeClass::kDiamond, 0});
        break;
      case Kind::kRegularPolygon:
        out.push_back({ShapeClass::kRegularPolygon, s.n});
        break;
      case Kind::kEllipse:
        out.push_back({ShapeClass::kEllipse, 0});
        break;
    }
  }
  return out;
}

std::vector<Scored> RefitRound::step() {
  if (done()) return {};
  const Step s = steps_[next_++];
  std::vector<Fit> fits;
  auto add = [&fits](std::optional<Fit> f) {
    if (f && std::isfinite(f->fit_error)) fits.push_back(std::move(*f));
  };
  switch (s.kind) {
    case Kind::kSegment:
      add(fit_segment(stroke_));
      break;
    case Kind::kPolyline:
      add(fit_polyline(stroke_, s.n - 1));
      break;
    case Kind::kArc:
      add(fit_arc(stroke_));
      break;
    case Kind::kCircle:
      circle_ = fit_circle(stroke_);
      add(circle_);
      break;
    case Kind::kTriangle:
      add(fit_polygon(stroke_, 3));
      break;
    case Kind::kQuadrilateral:
      quadrilateral_ = fit_polygon(stroke_, 4);
      add(quadrilateral_);
      break;
    case Kind::kRectangles:
      if (quadrilateral_) {
        for (Fit& f : fit_rectangles(stroke_, *quadrilateral_)) add(std::move(f));
      }
      break;
    case Kind::kRegularPolygon:
      if (circle_) {
        add(fit_regular_polygon(stroke_, s.n, circle_->params.center, circle_->params.radius_x));
      }
      break;
    case Kind::kEllipse:
      add(fit_ellipse(stroke_));
      break;
  }
  std::vector<Scored> scored =
      evaluate(stroke_, std::move(fits), tolerance_.epsilon, tolerance_.pen_radius, config_);
  std::vector<Scored> snaps;
  for (Scored& sc : scored) {
    if (sc.snap) snaps.push_back(std::move(sc));
  }
  found_snap_ = found_snap_ || !snaps.empty();
  return snaps;
}

} // namespace penshape::recognize_detail
