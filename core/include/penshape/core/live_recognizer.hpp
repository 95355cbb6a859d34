#pragma once
// The live (incremental) recognizer: fed sample by sample while the pen moves, it keeps the
// candidate shapes that can still fit, offers a preview before pen-up, and gives the final,
// certified answer at pen-up reusing what survived instead of recomputing from scratch.
//
// How candidates are kept. After a (re)fit on the samples so far, every plausible certified
// candidate stays alive while new samples arrive:
//   - convex polygon candidates (triangle, quadrilateral, rectangle, square, diamond, regular
//     polygon) run the on-line annulus decision (penshape/core/annulus/online.hpp): the
//     candidate is the template, delta = epsilon, seeded with the 48 fit points of the stroke
//     at the time of the fit; it dies as soon as NO translate of its epsilon-annulus contains
//     them and every later sample (a final NO for that template);
//   - the other candidates (segment, polyline, circle, ellipse, arc) die when a new sample lies
//     farther than epsilon from them at their fitted placement.
// A refit of every family runs when nothing is alive (at most every `refit_interval` samples),
// when the stroke closes or opens, or when the drawing has grown by half since the last fit
// (epsilon grows with it). The preview is the best candidate still alive.
//
// Pen-up (finish): each family's surviving candidate (moved to the on-line decision's verified
// translation) is certified against the whole stroke and used as that family's fit; families
// without a survivor, or whose survivor fails the certificate, are fitted afresh. The choice
// then follows recognize()'s rules exactly (same tolerance, plausibility and ranking), so the
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
  std::size_t refits = 0;            // full family fits run so far
  std::size_t alive = 0;             // candidates alive now
  std::size_t online_rejections = 0; // candidates killed by the on-line annulus decision
  std::size_t reused_at_finish = 0;  // families whose surviving fit finish() reused
};

class LiveRecognizer {
 public:
  explicit LiveRecognizer(const RecognizerConfig& config = {}, std::size_t refit_interval = 8);
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
