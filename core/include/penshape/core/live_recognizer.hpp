#pragma once
// The live (incremental) recognizer: fed sample by sample while the pen moves, it keeps the
// candidate shapes that can still fit, offers a preview before pen-up, and gives the final,
// certified answer at pen-up reusing what survived instead of recomputing from scratch.
//
// How candidates are kept. After a family fit on the stroke so far, every plausible certified
// candidate stays alive while new samples arrive:
//   - convex polygon candidates (triangle, quadrilateral, rectangle, square, diamond, regular
//     polygon) run the on-line annulus decision (penshape/core/annulus/online.hpp): the
//     candidate is the template, delta = epsilon, seeded (one batch) with every other fit point
//     of the stroke at the time of the fit; it dies as soon as NO translate of its
//     epsilon-annulus contains them and every later point fed to it (a final NO);
//   - the other candidates (segment, polyline, circle, ellipse, arc) die when a point fed to
//     them lies farther than epsilon from them at their fitted placement, except that with
//     kBounded open shapes grow with the pen: a point beyond the end of a segment, of a
//     polyline's last segment or of an arc, within epsilon of its line or circle and going on
//     in the same direction, extends the shape to it.
// The preview is the best-ranked candidate still alive, chosen as finish() chooses: once the
// stroke has closed, a closed shape only; a circle, ellipse or blunt-cornered shape gives way to
// a polygon of 5..8 corners alive that the stroke turns sharply at and that fits nearly as
// tightly (recognize.hpp, "Classes"). It is a candidate, not a certificate.
//
// Refit policy (LiveOptions::policy):
//   - kBounded (default; the daemon calls add() on every sample of a 1 kHz stream): the work of
//     one add() is bounded.
//       * The path used for live fits is thinned: a sample is kept only when it lies at least
//         thin_fraction * (drawing size so far) from the last kept one (a 1 kHz pen moves a
//         few hundredths of a millimetre per sample). The thinned path stays within that
//         distance of the pen path, far below epsilon (max_tolerance_fraction of the size).
//         Kept points number about (length / size + ln(size / first step)) / thin_fraction.
//         Candidates are fed the kept points only, and a live fit uses at most
//         max_fit_points of them (evenly strided beyond that).
//       * A refit is a round over the families that apply: at most ONE family is fitted and
//         certified per add() call (rectangle, square and diamond, fitted together, are
//         evaluated one per call), so a round is spread over about a dozen samples. Open
//         strokes try segment, arc and polylines; closed strokes circle, triangle,
//         quadrilateral, rectangle/square/diamond, ellipse and regular polygons. An open stroke
//         most of the way round (at least 1.5 times as long as its size, its end within 0.75
//         times its size of its start) first tries circle, triangle, quadrilateral,
//         rectangle/square/diamond and ellipse as prospects: shapes it can still become, kept
//         when every point of the fitted path is within epsilon of them (one-sided, estimated,
//         not certified) and the stroke does not trace them over. A new fit of a family
//         replaces that family's older candidate; older candidates of other families stay
//         while alive.
//       * A round starts, at most once per `interval` kept points, when nothing is alive
//         (checked on every call), or, checked every refit_interval kept points, when the
//         stroke closed, opened or came most of the way round, or when the drawing grew by
//         half since the last round. `interval` starts at refit_interval and doubles after
//         each round that found nothing (a scribble or writing), up to max_refit_interval; a
//         round that found a candidate resets it. The first round after the stroke closed may
//         come before its last corner is drawn: one more round follows it, refit_interval kept
//         points later, without back-off (so a polygon previews as one before pen-up).
//   - kEager (the previous behaviour, kept as the benchmark baseline): every sample is fed to
//     the candidates, and a full refit of every family on the whole stroke runs inside one
//     add() call when nothing is alive (at most every refit_interval samples), when the stroke
//     closes or opens, or when the drawing has grown by half since the last fit.
//
// Pen-up (finish, both policies): each family's surviving candidate of the stroke's closure
// (moved to the on-line decision's verified translation; not a prospect nor a grown open
// shape, which fit a partial stroke) is certified against the whole stroke (every sample,
// thinned within a certified tolerance as recognize() thins it: recognize.hpp, "Dense
// strokes") and used as that family's fit; families without such a survivor, or whose
// survivor fails the certificate, are fitted afresh on the whole stroke. The choice then
// follows recognize()'s rules exactly (same tolerance, plausibility and ranking), so the
// answer carries the same certificate guarantee; it can differ from recognize() on the same
// samples only where a reused fit ranks differently from a fresh one.
#include <cstddef>
#include <memory>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape {

struct LivePreview {
  ShapeClass shape = ShapeClass::kFreeform;
  ShapeParams params;
  std::vector<PointD> clean;
  std::size_t samples = 0; // samples seen when this preview was produced or last confirmed
};

struct LiveStats {
  std::size_t samples = 0;
  std::size_t refits = 0;            // refit rounds started so far (all families each)
  std::size_t family_fits = 0;       // single-family fits run so far
  std::size_t kept_points = 0;       // points of the thinned live path (kBounded)
  std::size_t alive = 0;             // candidates alive now
  std::size_t online_rejections = 0; // candidates killed by the on-line annulus decision
  std::size_t reused_at_finish = 0;  // families whose surviving fit finish() reused
};

enum class RefitPolicy {
  kBounded, // bounded work per add() (see the header comment); the default
  kEager,   // full refits inside add(): the previous behaviour, a baseline
};

// Limits: refit_interval >= 1, max_refit_interval >= refit_interval, max_fit_points >= 16,
// 0 <= thin_fraction <= 0.05 (InvalidInput otherwise).
struct LiveOptions {
  RefitPolicy policy = RefitPolicy::kBounded;
  std::size_t refit_interval = 8;      // kept points (kBounded) or samples (kEager)
  std::size_t max_refit_interval = 64; // kBounded: back-off cap
  std::size_t max_fit_points = 256;    // kBounded: points of the path a live fit uses
  double thin_fraction = 1.0 / 64.0;   // kBounded: spacing of kept points / drawing size
};

class LiveRecognizer {
 public:
  explicit LiveRecognizer(const RecognizerConfig& config = {}, const LiveOptions& options = {});
  ~LiveRecognizer();
  LiveRecognizer(LiveRecognizer&&) noexcept;
  LiveRecognizer& operator=(LiveRecognizer&&) noexcept;

  // Adds a sample. Throws InvalidInput for a non-finite or too large coordinate, or beyond
  // config.max_samples. Returns true when the preview changed.
  bool add(const StrokePoint& sample);

  [[nodiscard]] const LivePreview& preview() const;
  [[nodiscard]] LiveStats stats() const;

  // Pen-up: the final recognition of all samples added (InvalidInput as recognize() for fewer
  // than two distinct positions). The recognizer is then reset for the next stroke.
  Recognition finish();

  void reset();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

} // namespace penshape
