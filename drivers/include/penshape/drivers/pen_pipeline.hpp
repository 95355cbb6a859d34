#pragma once
// One device's decode path, shared by live devices and replay: report bytes -> PenDecoder ->
// sanity check -> StrokeSegmenter -> callbacks. `run_reader_loop` drives it from any
// ReportSource, so a replayed recording takes exactly the code path of a live device.
#include <atomic>
#include <cstdint>
#include <functional>
#include <span>

#include "penshape/drivers/device_profile.hpp"
#include "penshape/drivers/report_source.hpp"
#include "penshape/drivers/stroke_segmenter.hpp"

namespace penshape::drivers {

struct PipelineCounters {
  std::uint64_t reports = 0;       // every report read
  std::uint64_t pen_samples = 0;   // decoded pen samples delivered
  std::uint64_t other_reports = 0; // well-formed non-pen reports (pad buttons, mouse, …)
  std::uint64_t junk_reports = 0;  // unknown report ID or too short: dropped
  std::uint64_t out_of_range = 0;  // decoded, but coordinates beyond the maxima: dropped
  std::uint64_t strokes = 0;       // finished strokes delivered
  friend bool operator==(const PipelineCounters&, const PipelineCounters&) = default;
};

struct PenCallbacks {
  std::function<void(const PenSample&)> on_sample; // may be empty
  std::function<void(Stroke&&)> on_stroke;         // may be empty
};

// Every report as read, before it is decoded (so also those that give no sample), with its time;
// the span lives only for the call.
using ReportCallback = std::function<void(std::span<const std::uint8_t>, std::int64_t time_us)>;

class PenPipeline {
 public:
  PenPipeline(const DeviceProfile& profile, SegmenterOptions options, PenCallbacks callbacks,
              ReportCallback on_report = {});

  void on_report(std::span<const std::uint8_t> report, std::int64_t time_us);
  void on_idle(std::int64_t now_us);
  void on_end(); // end of stream or device lost: an open stroke ends cleanly

  [[nodiscard]] const PipelineCounters& counters() const { return counters_; }
  [[nodiscard]] const TabletInfo& tablet() const { return tablet_; }
  StrokeSegmenter& segmenter() { return segmenter_; }

 private:
  void deliver(std::optional<Stroke>&& stroke);

  PenDecoder decoder_; // a copy: the pipeline outlives nothing it borrows
  TabletInfo tablet_;
  StrokeSegmenter segmenter_;
  PenCallbacks callbacks_;
  ReportCallback on_report_; // may be empty
  PipelineCounters counters_;
};

enum class LoopEnd : std::uint8_t { kEnd, kGone, kStopped };

// Reads `source` until it ends, vanishes or `stop` becomes true, feeding `pipeline`; finishes
// any open stroke before returning. `poll` bounds each blocking read (and so the latency of
// debounce expiry and of noticing `stop` when the source cannot be interrupted).
LoopEnd run_reader_loop(ReportSource& source, PenPipeline& pipeline, const std::atomic<bool>& stop,
                        std::chrono::milliseconds poll = std::chrono::milliseconds(100));

} // namespace penshape::drivers
