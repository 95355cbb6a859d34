#pragma once
// Cuts a device's PenSamples into Strokes: a stroke runs from tip down to tip up. A tip-up that
// lasts less than the debounce time and is followed by tip down again is a bounce, not the end
// (its hover samples are dropped). Leaving proximity, the device vanishing, or the end of a
// recording ends an open stroke cleanly with a synthetic tip-up sample at the last position.
#include <cstdint>
#include <optional>

#include "penshape/types/stroke.hpp"

namespace penshape::drivers {

struct SegmenterOptions {
  // A tip-up shorter than this (then tip down again) does not end the stroke. 0 disables.
  std::int64_t tip_up_debounce_us = 12'000;
  // Tablets that never report leaving proximity: no sample for this long ends the stroke on
  // the next idle() call. 0 disables.
  std::int64_t silence_timeout_us = 250'000;
};

class StrokeSegmenter {
 public:
  explicit StrokeSegmenter(TabletInfo tablet, SegmenterOptions options = {});

  // Feeds one sample (times must not decrease; an earlier one is clamped). Returns the stroke
  // this sample finished, if any.
  std::optional<Stroke> feed(const PenSample& sample);
  // Time passes without samples (reader timeouts): finishes a stroke whose debounce window or
  // silence timeout has expired at `now_us`.
  std::optional<Stroke> idle(std::int64_t now_us);
  // The stream ends (end of recording, device unplugged): finishes any open stroke.
  std::optional<Stroke> finish();

  [[nodiscard]] bool in_stroke() const { return open_; }
  // Strokes get ids id_base + 1, id_base + 2, … (set before the first stroke).
  void set_next_id(std::uint64_t next) { next_id_ = next; }

 private:
  std::optional<Stroke> close(const PenSample& last_up);

  TabletInfo tablet_;
  SegmenterOptions options_;
  bool open_ = false;
  Stroke current_;
  std::optional<PenSample> pending_up_; // first tip-up sample, while debouncing
  std::int64_t last_time_ = INT64_MIN;
  std::uint64_t next_id_ = 1;
};

} // namespace penshape::drivers
