// The live recognizer (contract and policies in penshape/core/live_recognizer.hpp).
#include "penshape/core/live_recognizer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "recognize/classify/annulus_polish.hpp"
#include "recognize/classify/classifier.hpp"
#include "recognize/fitting/dot.hpp"
#include "recognize/live/live_candidate.hpp"
#include "recognize/live/live_path.hpp"
#include "recognize/live/live_round.hpp"
#include "recognize/thresholds.hpp"

namespace penshape {

using recognize_detail::Family;
using recognize_detail::Fit;
using recognize_detail::kGrowthForRefit;
using recognize_detail::LiveCandidate;
using recognize_detail::LivePath;
using recognize_detail::PreparedStroke;
using recognize_detail::RefitRound;
using recognize_detail::Scored;

namespace {

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

void check_options(const LiveOptions& o) {
  if (o.refit_interval < 1 || o.max_refit_interval < o.refit_interval || o.max_fit_points < 16 ||
      !(o.thin_fraction >= 0.0 && o.thin_fraction <= 0.05)) {
    throw InvalidInput(
        "live recognizer: options out of range (refit_interval >= 1, "
        "max_refit_interval >= refit_interval, max_fit_points >= 16, "
        "0 <= thin_fraction <= 0.05)");
  }
}

bool closed_family(ShapeClass c) {
  return c != ShapeClass::kSegment && c != ShapeClass::kPolyline && c != ShapeClass::kArc;
}

} // namespace

struct LiveRecognizer::State {
  RecognizerConfig config;
  LiveOptions options;
  std::vector<StrokePoint> samples;
  LivePath path;
  std::vector<LiveCandidate> candidates;
  std::optional<RefitRound> round; // kBounded: the round in progress
  LivePreview preview;
  LiveStats stats;
  std::size_t generation = 0; // rounds started
  std::size_t next_id = 0;
  std::size_t last_fit_points = 0; // kept points when the last round started
  std::size_t next_check = 0;      // kBounded: kept points at which triggers are checked next
  double last_fit_size = 0.0;
  bool last_fit_closed = false;
  int last_stage = 0;          // kBounded: RefitRound::stage of the last round
  std::size_t failures = 0;    // consecutive rounds without a snap (back-off)
  bool retry_closed = false;   // kBounded: the first closed round is done: one more round
  bool retried_closed = false; // ... which is granted once per stroke
  std::size_t preview_id = std::numeric_limits<std::size_t>::max();
  PointD preview_shift;
  std::size_t preview_version = 0;

  State(const RecognizerConfig& c, const LiveOptions& o)
      : config(c), options(o), path(o.policy == RefitPolicy::kBounded ? o.thin_fraction : 0.0) {}

  [[nodiscard]] bool bounded() const { return options.policy == RefitPolicy::kBounded; }

  [[nodiscard]] std::size_t interval() const {
    if (!bounded()) return options.refit_interval;
    std::size_t v = options.refit_interval;
    for (std::size_t k = 0; k < failures && v < options.max_refit_interval; ++k) v *= 2;
    return std::min(v, options.max_refit_interval);
  }

  [[nodiscard]] std::size_t alive() const {
    return static_cast<std::size_t>(std::count_if(candidates.begin(), candidates.end(),
                                                  [](const LiveCandidate& c) { return c.alive; }));
  }

  void feed(PointD p) {
    for (LiveCandidate& c : candidates) {
      const bool was = c.alive;
      if (!c.accept(p) && was && c.online) ++stats.online_rejections;
    }
    std::erase_if(candidates, [](const LiveCandidate& c) { return !c.alive; });
  }

  // --- kEager: the previous policy, a full refit of every family inside one call. ---
  void eager_refit() {
    ++stats.refits;
    ++generation;
    last_fit_points = path.points().size();
    last_fit_size = path.size();
    const ToleranceChoice tol = choose_tolerance(samples, config);
    const PreparedStroke s = recognize_detail::prepare_points(
        path.points(), recognize_detail::thinning_tolerance(config, tol.epsilon));
    last_fit_closed = recognize_detail::is_closed(s, tol.epsilon);
    std::vector<Fit> fits = recognize_detail::fit_all(s, config, tol.epsilon);
    stats.family_fits += fits.size();
    std::vector<Scored> scored =
        recognize_detail::evaluate(s, std::move(fits), tol.epsilon, tol.pen_radius, config);
    candidates.clear();
    for (Scored& sc : scored) {
      if (!sc.snap) continue;
      LiveCandidate c = LiveCandidate::make(std::move(sc), s, tol.epsilon, path.magnitude(), false);
      if (!c.alive) continue;
      c.generation = generation;
      c.id = next_id++;
      candidates.push_back(std::move(c));
    }
  }

  bool eager_add(PointD p) {
    feed(p);
    const std::size_t n = path.points().size();
    const bool due = n >= last_fit_points + options.refit_interval;
    if (!due) return update_preview();
    const bool none_alive = alive() == 0;
    const bool grown = path.size() > kGrowthForRefit * last_fit_size;
    bool closure_changed = false;
    if (!none_alive) {
      // Closing or opening the stroke changes which families apply.
      const ToleranceChoice tol = choose_tolerance(samples, config);
      // Closure reads the fit points only: no thinning needed.
      const PreparedStroke s = recognize_detail::prepare_points(path.points(), 0.0);
      closure_changed = recognize_detail::is_closed(s, tol.epsilon) != last_fit_closed;
    }
    if (none_alive || grown || closure_changed) eager_refit();
    return update_preview();
  }

  // --- kBounded: rounds of one family fit per call, on the thinned, capped path. ---
  void start_round(const PreparedStroke& s, const ToleranceChoice& tol) {
    ++stats.refits;
    ++generation;
    last_fit_points = path.kept().size();
    last_fit_size = path.size();
    round.emplace(s, tol, path.kept().size(), config);
    last_fit_closed = round->closed();
    last_stage = round->stage();
  }

  void round_step() {
    std::vector<Scored> snaps = round->step();
    ++stats.family_fits;
    const std::vector<PointD>& kept = path.kept();
    const std::span<const PointD> later =
        std::span<const PointD>(kept).subspan(std::min(round->kept_at_start(), kept.size()));
    for (Scored& sc : snaps) {
      LiveCandidate c = LiveCandidate::make(std::move(sc), round->stroke(), round->epsilon(),
                                            path.magnitude(), true);
      c.prospect = round->last_step_prospective();
      // Catch up with the points kept since the round's snapshot.
      if (!c.alive || !c.accept_all(later)) continue;
      c.generation = generation;
      c.id = next_id++;
      std::erase_if(candidates, [&](const LiveCandidate& old) {
        return old.generation < generation && old.family == c.family;
      });
      candidates.push_back(std::move(c));
    }
    if (!round->done()) return;
    // Older candidates of families the round did not refit stay while they are alive: being
    // alive is what "can still fit" means (a prospect of a closed shape keeps its place while
    // the stroke closes, even if the closed fit does not certify yet); finish() filters by
    // closure and certifies.
    // A round started as the stroke closes may come before its last corner: one more round
    // then, as soon as refit_interval more points are kept (no back-off, no growth needed).
    retry_closed = round->closed() && !retried_closed;
    retried_closed = retried_closed || retry_closed;
    if (round->found_snap()) {
      failures = 0;
    } else if (!retry_closed) {
      ++failures;
    }
    round.reset();
  }

  bool bounded_add() {
    if (path.kept_grew()) feed(path.kept().back());
    if (round) {
      round_step(); // at most one family per call
    } else if (path.kept().size() >= last_fit_points + interval()) {
      // Nothing alive is known at once; the other triggers need the stroke's shape, so they
      // are looked at only every refit_interval kept points.
      const bool none_alive = alive() == 0;
      if (none_alive || path.kept().size() >= next_check) {
        next_check = path.kept().size() + options.refit_interval;
        const ToleranceChoice tol = path.tolerance(config);
        // The live path is thinned and capped already (LivePath): no certified thinning on
        // top, whose tau would only loosen the previews' certificates.
        const PreparedStroke s =
            recognize_detail::prepare_points(path.fit_path(options.max_fit_points), 0.0);
        const bool grown = path.size() > kGrowthForRefit * last_fit_size;
        // Closing or opening the stroke, or coming most of the way round, changes which
        // families apply.
        const bool stage_changed = RefitRound::stage(s, tol.epsilon) != last_stage;
        if (none_alive || grown || stage_changed || retry_closed) {
          retry_closed = false;
          start_round(s, tol);
          round_step();
        }
      }
    }
    return update_preview();
  }

  // The preview is the best-ranked candidate still alive, as finish() chooses: a closed stroke
  // shows a closed shape (an open one fitted earlier may still be alive), and a candidate yields
  // to a sharp polygon alive that fits nearly as tightly (kSharpPolygonSlack). Returns whether it
  // changed.
  bool update_preview() {
    double tightest = INFINITY;
    for (const LiveCandidate& c : candidates) {
      if (c.alive && c.sharp_polygon) tightest = std::min(tightest, c.fit_measure);
    }
    const LiveCandidate* best = nullptr;
    for (const LiveCandidate& c : candidates) {
      if (!c.alive || (c.yields_to_sharp_polygon &&
                       recognize_detail::kSharpPolygonSlack * c.fit_measure >= tightest)) {
        continue;
      }
      if (last_fit_closed && !closed_family(c.fit.shape)) continue;
      if (best == nullptr || c.rank < best->rank) best = &c;
    }
    stats.alive = alive();
    preview.samples = samples.size();
    if (best == nullptr) {
      const bool changed = preview.shape != ShapeClass::kFreeform;
      if (changed) {
        preview = LivePreview{};
        preview.samples = samples.size();
      }
      preview_id = std::numeric_limits<std::size_t>::max();
      return changed;
    }
    const PointD shift = best->shift();
    // The previous policy redrew the preview on every sample; the bounded one only when the
    // candidate or its placement changed.
    if (bounded() && best->id == preview_id && best->version == preview_version &&
        shift == preview_shift) {
      return false;
    }
    const ShapeClass before = preview.shape;
    const Fit f = best->placed();
    preview.shape = f.shape;
    preview.params = f.params;
    preview.clean = f.clean.kind == recognize_detail::CleanShape::Kind::kPolyline
                        ? f.clean.path
                        : f.clean.sample(path.size() / 40.0);
    const bool changed =
        best->id != preview_id || !(shift == preview_shift) || before != preview.shape;
    preview_id = best->id;
    preview_shift = shift;
    return changed;
  }
};

LiveRecognizer::LiveRecognizer(const RecognizerConfig& config, const LiveOptions& options) {
  check_options(options);
  state_ = std::make_unique<State>(config, options);
}
LiveRecognizer::~LiveRecognizer() = default;
LiveRecognizer::LiveRecognizer(LiveRecognizer&&) noexcept = default;
LiveRecognizer& LiveRecognizer::operator=(LiveRecognizer&&) noexcept = default;

void LiveRecognizer::reset() { state_ = std::make_unique<State>(state_->config, state_->options); }

const LivePreview& LiveRecognizer::preview() const { return state_->preview; }

LiveStats LiveRecognizer::stats() const {
  LiveStats s = state_->stats;
  s.samples = state_->samples.size();
  s.kept_points = state_->path.kept().size();
  return s;
}

bool LiveRecognizer::add(const StrokePoint& sample) {
  State& st = *state_;
  check_sample(sample, st.samples.size(), st.config);
  st.samples.push_back(sample);
  if (!st.path.add({sample.x, sample.y})) return false;
  if (st.path.points().size() < 2) return false;
  return st.bounded() ? st.bounded_add() : st.eager_add(st.path.points().back());
}

Recognition LiveRecognizer::finish() {
  State& st = *state_;
  recognize_detail::validate_samples(st.samples, st.config);
  const ToleranceChoice tol = choose_tolerance(st.samples, st.config);
  if (recognize_detail::is_dot(st.samples)) {
    Recognition dot = recognize_detail::dot_recognition(st.samples, tol);
    reset();
    return dot;
  }
  const PreparedStroke s = recognize_detail::prepare_points(
      st.path.points(), recognize_detail::thinning_tolerance(st.config, tol.epsilon));
  const bool closed = recognize_detail::is_closed(s, tol.epsilon);

  // Survivors of the right kind (closed or open) are certified against the whole stroke.
  std::vector<Fit> reused;
  for (const LiveCandidate& c : st.candidates) {
    if (!c.alive || !c.reusable() || closed_family(c.fit.shape) != closed) continue;
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
  const std::size_t reused_count = kept.size();
  // Families that cannot beat the best survivor are not fitted again: a rank is at least the
  // family's price for its parameters (polygons drawn sharp win on their corners, not rank).
  if (!kept.empty()) {
    const double best = kept.front().rank;
    for (const Family& fam : recognize_detail::all_families(st.config)) {
      if (recognize_detail::minimum_rank(fam) >= best && !recognize_detail::wins_on_corners(fam)) {
        have.push_back(fam);
      }
    }
  }
  std::vector<Scored> fresh =
      recognize_detail::evaluate(s, recognize_detail::fit_all(s, st.config, tol.epsilon, have),
                                 tol.epsilon, tol.pen_radius, st.config);
  for (Scored& sc : fresh) kept.push_back(std::move(sc));
  recognize_detail::settle(s, kept);
  if (!kept.empty() && kept.front().snap) {
    recognize_detail::polish_with_annulus(s, kept.front(), st.config);
  }
  Recognition out = recognize_detail::choose(std::move(kept), tol.epsilon, tol.pen_radius);
  reset();
  state_->stats.reused_at_finish = reused_count;
  return out;
}

} // namespace penshape
