#include "penshape/drivers/stroke_segmenter.hpp"

#include <climits>

namespace penshape::drivers {

StrokeSegmenter::StrokeSegmenter(TabletInfo tablet, SegmenterOptions options)
    : tablet_(std::move(tablet)), options_(options) {}

std::optional<Stroke> StrokeSegmenter::close(const PenSample& last_up) {
  current_.samples.push_back(last_up);
  Stroke done = std::move(current_);
  current_ = Stroke{};
  open_ = false;
  pending_up_.reset();
  return done;
}

std::optional<Stroke> StrokeSegmenter::feed(const PenSample& in) {
  PenSample s = in;
  if (last_time_ != INT64_MIN && s.time_us < last_time_) s.time_us = last_time_;
  last_time_ = s.time_us;

  std::optional<Stroke> finished;
  if (open_ && pending_up_) {
    const bool expired = s.time_us - pending_up_->time_us >= options_.tip_up_debounce_us;
    if (s.tip && s.in_range && !expired) {
      pending_up_.reset(); // a bounce: the stroke goes on
    } else if (expired || !s.in_range) {
      finished = close(*pending_up_);
    } else {
      return std::nullopt; // still hovering inside the debounce window
    }
  }
  if (!open_) {
    if (s.tip && s.in_range) {
      open_ = true;
      current_ = Stroke{};
      current_.id = next_id_++;
      current_.tablet = tablet_;
      current_.samples.push_back(s);
    }
    return finished;
  }
  if (s.tip && s.in_range) {
    current_.samples.push_back(s);
  } else if (!s.in_range) {
    PenSample up = s;
    up.tip = false;
    up.pressure = 0;
    finished = close(up);
  } else if (options_.tip_up_debounce_us > 0) {
    pending_up_ = s;
  } else {
    finished = close(s);
  }
  return finished;
}

std::optional<Stroke> StrokeSegmenter::idle(std::int64_t now_us) {
  if (!open_) return std::nullopt;
  if (pending_up_ && now_us - pending_up_->time_us >= options_.tip_up_debounce_us) {
    return close(*pending_up_);
  }
  if (!pending_up_ && options_.silence_timeout_us > 0 && !current_.samples.empty() &&
      now_us - current_.samples.back().time_us >= options_.silence_timeout_us) {
    return finish();
  }
  return std::nullopt;
}

std::optional<Stroke> StrokeSegmenter::finish() {
  if (!open_) return std::nullopt;
  if (pending_up_) return close(*pending_up_);
  PenSample up = current_.samples.back();
  up.tip = false;
  up.pressure = 0;
  up.in_range = false;
  return close(up);
}

} // namespace penshape::drivers
