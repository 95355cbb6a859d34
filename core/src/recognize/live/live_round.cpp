// One-family-per-step refit rounds (see live_round.hpp). The families and the fitters are the
// ones fit_all() uses, so a round proposes what a full refit would, only spread over calls.
#include "recognize/live/live_round.hpp"

#include <cmath>

#include "recognize/classify/sharp_polygon.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

// Tracing limit and rank weights: the classifier's (classifier.hpp), shared with snaps.

} // namespace

RefitRound::RefitRound(PreparedStroke stroke, const ToleranceChoice& tolerance,
                       std::size_t kept_at_start, const RecognizerConfig& config)
    : stroke_(std::move(stroke)),
      tolerance_(tolerance),
      kept_at_start_(kept_at_start),
      config_(config),
      closed_(is_closed(stroke_, tolerance.epsilon)),
      stage_(stage(stroke_, tolerance.epsilon)) {
  // Cheap, common families first: the preview appears sooner.
  if (!closed_) {
    // A stroke most of the way round is more likely a closed shape than an open one.
    if (stage_ == 1) {
      for (const Kind k : {Kind::kTriangle, Kind::kCircle, Kind::kQuadrilateral, Kind::kRectangles,
                           Kind::kEllipse}) {
        steps_.push_back({k, 0, true});
      }
    }
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
  for (std::size_t n = kMinPolygonCorners; n <= kMaxPolygonCorners; ++n) {
    steps_.push_back({Kind::kPolygon, n});
  }
}

int RefitRound::stage(const PreparedStroke& stroke, double epsilon) {
  if (is_closed(stroke, epsilon)) return 2;
  return stroke.length >= kProspectLength * stroke.size && stroke.gap <= kProspectGap * stroke.size
             ? 1
             : 0;
}

std::vector<Scored> RefitRound::step() {
  if (done()) return {};
  if (!pending_.empty()) {
    std::vector<Fit> one;
    one.push_back(std::move(pending_.back()));
    pending_.pop_back();
    return finish_step(std::move(one), last_prospective_);
  }
  const Step s = steps_[next_++];
  last_prospective_ = s.prospective;
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
    case Kind::kPolygon:
      fits = polygon_fits(stroke_, s.n);
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
  while (fits.size() > 1) { // one certification per step
    pending_.push_back(std::move(fits.back()));
    fits.pop_back();
  }
  return finish_step(std::move(fits), s.prospective);
}

std::vector<Scored> RefitRound::finish_step(std::vector<Fit> fits, bool prospective) {
  std::vector<Scored> scored = prospective ? prospects(std::move(fits))
                                           : evaluate(stroke_, std::move(fits), tolerance_.epsilon,
                                                      tolerance_.pen_radius, config_);
  std::vector<Scored> snaps;
  for (Scored& sc : scored) {
    if (sc.snap) snaps.push_back(std::move(sc));
  }
  found_snap_ = found_snap_ || !snaps.empty();
  return snaps;
}

std::vector<Scored> RefitRound::prospects(std::vector<Fit> fits) const {
  const double eps = tolerance_.epsilon;
  const double stroke_length = path_length(stroke_.fit_points);
  std::vector<Scored> out;
  for (Fit& f : fits) {
    double worst = 0.0;
    for (const PointD& p : stroke_.points) worst = std::max(worst, f.clean.distance_to(p));
    if (!(worst <= eps)) continue;
    if (stroke_length > kMaxTracing * path_length(f.clean.sample(stroke_.size / 64.0))) continue;
    Scored sc;
    // The one-sided distance stands in for the certified bound (in the rank and fit_measure).
    sc.candidate.certificate.bound = worst;
    sc.candidate.rms = rms_distance(stroke_.fit_points, f.clean);
    sc.rank = fit_measure(sc.candidate) / eps + kPricePerParameter * degrees_of_freedom(f);
    sc.snap = true;
    sc.fit = std::move(f);
    out.push_back(std::move(sc));
  }
  return out;
}

} // namespace penshape::recognize_detail
