#include "penshape/drivers/pen_pipeline.hpp"

namespace penshape::drivers {

PenPipeline::PenPipeline(const DeviceProfile& profile, SegmenterOptions options,
                         PenCallbacks callbacks, ReportCallback on_report)
    : decoder_(profile.decoder),
      tablet_(profile.info),
      segmenter_(profile.info, options),
      callbacks_(std::move(callbacks)),
      on_report_(std::move(on_report)) {}

void PenPipeline::deliver(std::optional<Stroke>&& stroke) {
  if (!stroke) return;
  ++counters_.strokes;
  if (callbacks_.on_stroke) callbacks_.on_stroke(std::move(*stroke));
}

void PenPipeline::on_report(std::span<const std::uint8_t> report, std::int64_t time_us) {
  ++counters_.reports;
  if (on_report_) on_report_(report, time_us);
  PenSample s;
  switch (decoder_.decode(report, time_us, s)) {
    case DecodeStatus::kJunk:
      ++counters_.junk_reports;
      return;
    case DecodeStatus::kOther:
      ++counters_.other_reports;
      return;
    case DecodeStatus::kPen:
      break;
  }
  // A coordinate beyond the logical maximum is a corrupt frame (the descriptor's range is the
  // device's promise), not a pen position.
  if (s.x < 0 || s.y < 0 || (tablet_.x_max > 0 && s.x > tablet_.x_max) ||
      (tablet_.y_max > 0 && s.y > tablet_.y_max) ||
      (tablet_.pressure_max > 0 && s.pressure > tablet_.pressure_max)) {
    ++counters_.out_of_range;
    return;
  }
  ++counters_.pen_samples;
  if (callbacks_.on_sample) callbacks_.on_sample(s);
  deliver(segmenter_.feed(s));
}

void PenPipeline::on_idle(std::int64_t now_us) { deliver(segmenter_.idle(now_us)); }

void PenPipeline::on_end() { deliver(segmenter_.finish()); }

LoopEnd run_reader_loop(ReportSource& source, PenPipeline& pipeline, const std::atomic<bool>& stop,
                        std::chrono::milliseconds poll) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(64);
  LoopEnd end = LoopEnd::kStopped;
  while (!stop.load(std::memory_order_relaxed)) {
    std::int64_t t = 0;
    const ReadStatus st = source.read(bytes, t, poll);
    if (st == ReadStatus::kReport) {
      pipeline.on_report(bytes, t);
    } else if (st == ReadStatus::kTimeout) {
      pipeline.on_idle(source.now_us());
    } else {
      end = st == ReadStatus::kGone ? LoopEnd::kGone : LoopEnd::kEnd;
      break;
    }
  }
  if (stop.load(std::memory_order_relaxed)) end = LoopEnd::kStopped;
  pipeline.on_end();
  return end;
}

} // namespace penshape::drivers
