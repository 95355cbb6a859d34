#pragma once
// Replay: a recording drives the very path a live device takes (ReportSource -> reader loop ->
// PenPipeline), either at the original speed (waits between reports as recorded) or as fast as
// possible (timestamps kept, no waiting).
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "penshape/drivers/pen_pipeline.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/report_source.hpp"

namespace penshape::drivers {

enum class ReplaySpeed : std::uint8_t { kOriginal, kAsFastAsPossible };

// A ReportSource over recorded events. Report times are the recorded ones (relative to the
// first event). At kOriginal the source sleeps (interruptibly) until each event is due; at
// kAsFastAsPossible it never sleeps and reports the gap to the next event as timeouts when that
// gap exceeds the caller's poll period, so idle handling matches the live path; a gap of any
// length costs a number of timeouts logarithmic in it.
class RecordingSource final : public ReportSource {
 public:
  RecordingSource(std::vector<HidEvent> events, ReplaySpeed speed);

  ReadStatus read(std::vector<std::uint8_t>& bytes, std::int64_t& time_us,
                  std::chrono::milliseconds timeout) override;
  std::int64_t now_us() const override;
  void interrupt() override;

 private:
  std::int64_t gap_tick(std::int64_t left, std::int64_t poll_us);

  std::vector<HidEvent> events_;
  ReplaySpeed speed_;
  std::size_t next_ = 0;
  std::int64_t t0_ = 0; // first event's time
  std::int64_t virtual_now_ = 0;
  std::int64_t gap_polls_ = 1; // polls the next timeout in this gap steps over
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  bool interrupted_ = false;
};

struct ReplayResult {
  TabletInfo tablet;
  std::string family;                            // report family of the table row (or "hid")
  std::string layout;                            // origin of the primary pen layout
  SizeSource size_source = SizeSource::kUnknown; // where tablet's resolution came from
  std::vector<PenSample> samples;
  std::vector<Stroke> strokes;
  PipelineCounters counters;
};

// Builds the device profile from the recording (descriptor, identity, vendor strings; set
// recording.identity yourself when the file had no I: line) and runs it through the reader
// loop on the calling thread. Throws DescriptorError / std::invalid_argument like
// build_profile.
ReplayResult replay(const Recording& recording, ReplaySpeed speed, SegmenterOptions options = {});

} // namespace penshape::drivers
