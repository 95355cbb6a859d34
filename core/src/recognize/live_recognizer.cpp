// The live recognizer (contract in penshape/core/live_recognizer.hpp).
#include "penshape/core/live_recognizer.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "annulus_polish.hpp"
#include "classifier.hpp"
#include "penshape/core/annulus/online.hpp"

namespace penshape {

using recognize_detail::Family;
using recognize_detail::Fit;
using recognize_detail::PreparedStroke;
using recognize_detail::Scored;
using recognize_detail::operator+;

namespace {

bool convex_polygon(ShapeClass c) {
  switch (c) {
    case ShapeClass::kTriangle:
    case ShapeClass::kQuadrilateral:
    case ShapeClass::kRectangle:
    case ShapeClass::kSquare:
    case ShapeClass::kDiamond:
    case ShapeClass::kRegularPolygon:
      return true;
    default:
      return false;
  }
}

// A candidate kept alive while samples arrive.
struct LiveCandidate {
  Fit fit;
  double rank = 0.0;
  std::optional<annulus::OnlineContainment> online; // convex polygons
  double epsilon = 0.0;
  bool alive = true;

  // Feeds one sample; false once the candidate can no longer fit.
  bool accept(PointD p) {
    if (!alive) return false;
    if (online) {
      alive = online->add(p) != Answer::kNo;
    } else {
      alive = fit.clean.distance_to(p) <= epsilon;
    }
    return alive;
  }

  // The fit moved to the on-line decision's verified translation (when it has one).
  [[nodiscard]] Fit placed() const {
    Fit f = fit;
    if (!online || online->answer() != Answer::kYes) return f;
    const PointD t{online->placement().tx, online->placement().ty};
    for (PointD& v : f.clean.path) v = v + t;
    for (PointD& v : f.params.vertices) v = v + t;
    f.params.center = f.params.center + t;
    return f;
  }
};

void check_sample(const StrokePoint& s, std::size_t index, const RecognizerConfig& config) {
  if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.t)) {
    throw InvalidInput("live recognizer: sample " + std::to_string(index) + " is not finite");
  }
  if (std::abs(s.x) > 1e9 || std::abs(s.y) > 1e9) {
    throw InvalidInput("live recognizer: sample " + std::to_string(index) +
                       " has a coordinate beyond the limit |x|, |y| <= 1e9");
  }
  if (index >= config.max_samples) {
    throw InvalidInput("live recognizer: more samples than the limit of " +
                       std::to_string(config.max_samples));
  }
}

} // namespace

struct LiveRecognizer::State {
  RecognizerConfig config;
  std::size_t refit_interval = 8;
  std::vector<StrokePoint> samples;
  std::vector<PointD> points; // deduplicated
  std::vector<LiveCandidate> candidates;
  LivePreview preview;
  LiveStats stats;
  std::size_t last_fit_samples = 0;
  double last_fit_size = 0.0;
  bool last_fit_closed = false;
  PointD lo, hi;

  [[nodiscard]] double size() const { return std::hypot(hi.x - lo.x, hi.y - lo.y); }

  void refit() {
    ++stats.refits;
    last_fit_samples = points.size();
    last_fit_size = size();
    const ToleranceChoice tol = choose_tolerance(samples, config);
    const PreparedStroke s = recognize_detail::prepare_points(points);
    last_fit_closed = recognize_detail::is_closed(s, tol.epsilon);
    std::vector<Scored> scored = recognize_detail::evaluate(
        s, recognize_detail::fit_all(s, config, tol.epsilon), tol.epsilon, tol.pen_radius, config);
    candidates.clear();
    const double magnitude =
        std::max({std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)});
    for (Scored& sc : scored) {
      if (!sc.snap) continue;
      LiveCandidate c;
      c.rank = sc.rank;
      c.epsilon = tol.epsilon;
      if (convex_polygon(sc.fit.shape)) {
        try {
          const annulus::TemplatePolygon t = annulus::make_convex_template(sc.fit.params.vertices);
          c.online.emplace(t, annulus::OuterOffset::kRound, tol.epsilon, magnitude);
          // Seeded with the fit points (48 along the stroke so far; the certificate already
          // covers every sample at the fitted placement), then fed every new sample.
          for (const PointD& p : s.fit_points) c.online->add(p);
          if (c.online->answer() == Answer::kNo) continue; // cannot happen for a certified fit
        } catch (const InvalidInput&) {
          c.online.reset(); // degenerate template: fall back to the fixed placement
        }
      }
      c.fit = std::move(sc.fit);
      candidates.push_back(std::move(c));
    }
    update_preview(true);
  }

  // The preview is the best-ranked candidate still alive. Returns whether it changed.
  bool update_preview(bool force) {
    const LiveCandidate* best = nullptr;
    std::size_t alive = 0;
    for (const LiveCandidate& c : candidates) {
      if (!c.alive) continue;
      ++alive;
      if (best == nullptr || c.rank < best->rank) best = &c;
    }
    stats.alive = alive;
    const ShapeClass before = preview.shape;
    if (best == nullptr) {
      const bool changed = preview.shape != ShapeClass::kFreeform || force;
      preview = LivePreview{};
      preview.samples = samples.size();
      return changed && before != ShapeClass::kFreeform;
    }
    const Fit f = best->placed();
    preview.shape = f.shape;
    preview.params = f.params;
    preview.clean = f.clean.kind == recognize_detail::CleanShape::Kind::kPolyline
                        ? f.clean.path
                        : f.clean.sample(size() / 40.0);
    preview.samples = samples.size();
    return force || before != preview.shape;
  }
};

LiveRecognizer::LiveRecognizer(const RecognizerConfig& config, std::size_t refit_interval)
    : state_(std::make_unique<State>()) {
  state_->config = config;
  state_->refit_interval = std::max<std::size_t>(1, refit_interval);
}
LiveRecognizer::~LiveRecognizer() = default;
LiveRecognizer::LiveRecognizer(LiveRecognizer&&) noexcept = default;
LiveRecognizer& LiveRecognizer::operator=(LiveRecognizer&&) noexcept = default;

void LiveRecognizer::reset() {
  const RecognizerConfig config = state_->config;
  const std::size_t interval = state_->refit_interval;
  state_ = std::make_unique<State>();
  state_->config = config;
  state_->refit_interval = interval;
}

const LivePreview& LiveRecognizer::preview() const { return state_->preview; }

LiveStats LiveRecognizer::stats() const {
  LiveStats s = state_->stats;
  s.samples = state_->samples.size();
  return s;
}

bool LiveRecognizer::add(const StrokePoint& sample) {
  State& st = *state_;
  check_sample(sample, st.samples.size(), st.config);
  st.samples.push_back(sample);
  const PointD p{sample.x, sample.y};
  if (!st.points.empty() && st.points.back() == p) return false;
  if (st.points.empty()) st.lo = st.hi = p;
  st.lo = {std::min(st.lo.x, p.x), std::min(st.lo.y, p.y)};
  st.hi = {std::max(st.hi.x, p.x), std::max(st.hi.y, p.y)};
  st.points.push_back(p);
  if (st.points.size() < 2) return false;

  for (LiveCandidate& c : st.candidates) {
    const bool was = c.alive;
    if (!c.accept(p) && was && c.online) ++st.stats.online_rejections;
  }
  bool changed = st.update_preview(false);

  const bool due = st.points.size() >= st.last_fit_samples + st.refit_interval;
  const bool none_alive = st.stats.alive == 0;
  const bool grown = st.size() > 1.5 * st.last_fit_size;
  bool closure_changed = false;
  if (due && !none_alive) {
    // Closing or opening the stroke changes which families apply.
    const ToleranceChoice tol = choose_tolerance(st.samples, st.config);
    const PreparedStroke s = recognize_detail::prepare_points(st.points);
    closure_changed = recognize_detail::is_closed(s, tol.epsilon) != st.last_fit_closed;
  }
  if (due && (none_alive || grown || closure_changed)) {
    const ShapeClass before = st.preview.shape;
    st.refit();
    changed = changed || st.preview.shape != before;
  }
  return changed;
}

Recognition LiveRecognizer::finish() {
  State& st = *state_;
  recognize_detail::validate_samples(st.samples, st.config);
  const ToleranceChoice tol = choose_tolerance(st.samples, st.config);
  const PreparedStroke s = recognize_detail::prepare_points(st.points);
  const bool closed = recognize_detail::is_closed(s, tol.epsilon);

  // Survivors of the right kind (closed or open) are certified against the whole stroke.
  std::vector<Fit> reused;
  for (const LiveCandidate& c : st.candidates) {
    if (!c.alive || st.last_fit_closed != closed) continue;
    reused.push_back(c.placed());
  }
  std::vector<Scored> scored =
      recognize_detail::evaluate(s, std::move(reused), tol.epsilon, tol.pen_radius, st.config);
  std::vector<Family> have;
  std::vector<Scored> kept;
  for (Scored& sc : scored) {
    if (!sc.snap) continue;
    have.push_back(recognize_detail::family_of(sc.fit));
    kept.push_back(std::move(sc));
  }
  st.stats.reused_at_finish = kept.size();
  // Families that cannot beat the best survivor are not fitted again: a rank is at least the
  // family's price for its parameters.
  if (!kept.empty()) {
    const double best = kept.front().rank;
    for (const Family& fam : recognize_detail::all_families(st.config)) {
      if (recognize_detail::minimum_rank(fam) >= best) have.push_back(fam);
    }
  }
  std::vector<Scored> fresh =
      recognize_detail::evaluate(s, recognize_detail::fit_all(s, st.config, tol.epsilon, have),
                                 tol.epsilon, tol.pen_radius, st.config);
  for (Scored& sc : fresh) kept.push_back(std::move(sc));
  std::stable_sort(kept.begin(), kept.end(), [](const Scored& a, const Scored& b) {
    if (a.snap != b.snap) return a.snap;
    return a.rank < b.rank;
  });
  if (!kept.empty() && kept.front().snap) {
    recognize_detail::polish_with_annulus(s, kept.front(), st.config);
  }
  Recognition out = recognize_detail::choose(std::move(kept), tol.epsilon, tol.pen_radius);
  const LiveStats stats = st.stats;
  reset();
  state_->stats.reused_at_finish = stats.reused_at_finish;
  return out;
}

} // namespace penshape
