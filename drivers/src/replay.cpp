#include "penshape/drivers/replay.hpp"

namespace penshape::drivers {

RecordingSource::RecordingSource(std::vector<HidEvent> events, ReplaySpeed speed)
    : events_(std::move(events)), speed_(speed), start_(std::chrono::steady_clock::now()) {
  if (!events_.empty()) t0_ = events_.front().time_us;
}

std::int64_t RecordingSource::now_us() const {
  if (speed_ == ReplaySpeed::kAsFastAsPossible) {
    std::lock_guard lock(mutex_);
    return virtual_now_;
  }
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() -
                                                               start_)
      .count();
}

void RecordingSource::interrupt() {
  {
    std::lock_guard lock(mutex_);
    interrupted_ = true;
  }
  cv_.notify_all();
}

// The next timeout's step in a gap of `left` µs. Live, a gap of g µs is g / poll timeouts; a
// recording may hold a gap of years, so the steps double (1, 1, 2, 4... polls) and stay whole
// polls that end before the report, landing last on the live path's last timeout. Idle handling
// only asks whether a deadline has passed since the last sample, so these timeouts close the same
// strokes as every live one would.
std::int64_t RecordingSource::gap_tick(std::int64_t left, std::int64_t poll_us) {
  const std::int64_t polls_before_due = (left - 1) / poll_us;
  const std::int64_t polls = std::min(gap_polls_, polls_before_due);
  gap_polls_ = polls * 2;
  return polls * poll_us;
}

ReadStatus RecordingSource::read(std::vector<std::uint8_t>& bytes, std::int64_t& time_us,
                                 std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  if (interrupted_ || next_ >= events_.size()) return ReadStatus::kEnd;
  const HidEvent& e = events_[next_];
  const std::int64_t due = e.time_us - t0_;
  const std::int64_t timeout_us =
      std::chrono::duration_cast<std::chrono::microseconds>(timeout).count();
  if (speed_ == ReplaySpeed::kAsFastAsPossible) {
    // Virtual time: a gap longer than the poll period is a timeout, as it would be live.
    if (timeout_us > 0 && due - virtual_now_ > timeout_us) {
      virtual_now_ += gap_tick(due - virtual_now_, timeout_us);
      return ReadStatus::kTimeout;
    }
  } else {
    const auto due_at = start_ + std::chrono::microseconds(due);
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    if (cv_.wait_until(lock, std::min(due_at, deadline), [&] { return interrupted_; })) {
      return ReadStatus::kEnd;
    }
    if (std::chrono::steady_clock::now() < due_at) return ReadStatus::kTimeout;
  }
  virtual_now_ = std::max(virtual_now_, due);
  gap_polls_ = 1;
  bytes = e.bytes;
  time_us = due;
  ++next_;
  return ReadStatus::kReport;
}

ReplayResult replay(const Recording& recording, ReplaySpeed speed, SegmenterOptions options) {
  const DeviceProfile profile =
      build_profile(recording.identity, recording.descriptor, recording.vendor_strings);
  ReplayResult result;
  result.tablet = profile.info;
  result.family = profile.family;
  result.size_source = profile.size_source;
  if (!profile.decoder.layouts().empty()) result.layout = profile.decoder.layouts()[0].origin;
  PenPipeline pipeline(profile, options,
                       {.on_sample = [&](const PenSample& s) { result.samples.push_back(s); },
                        .on_stroke = [&](Stroke&& s) { result.strokes.push_back(std::move(s)); }});
  RecordingSource source(recording.events, speed);
  const std::atomic<bool> stop{false};
  run_reader_loop(source, pipeline, stop);
  result.counters = pipeline.counters();
  return result;
}

} // namespace penshape::drivers
