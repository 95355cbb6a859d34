#pragma once
// The daemon's SampleSink: device events and samples go straight to the hub (the reader thread
// only copies and queues); finished strokes go to the stroke lane for their ink polygon and shape
// (grouped with the device's recent strokes, in order, when the analyzer groups:
// live_grouping.hpp), then to the hub, and, for subscribers that ask, to the geometry lane for
// their deconstruction (StrokeDeconstructed); strokes in progress get previews on the idle-priority
// preview lane now and then, only while some subscriber asks for previews. A preview still queued
// or running when its stroke ends is cancelled: the stroke's final shape supersedes it.
// Hold to snap (snap_trigger hold or both): the reader thread tells from each sample when the pen
// held still, hands the stroke so far to the device's strand, and once it snapped makes the shape
// follow the pen (FOLLOW events, published like samples).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "daemon_state.hpp"
#include "hold_snap.hpp"
#include "hold_state.hpp"
#include "live_grouping.hpp"
#include "penshape/core/ink.hpp"

namespace penshape::daemon {

class Pipeline final : public SampleSink {
 public:
  // At most one preview per device per interval (about three display frames).
  static constexpr std::chrono::milliseconds kPreviewInterval{50};
  // A grouped stroke's ink polygon is built ahead each time this many samples arrived (its
  // chunks' length: InkBuilder).
  static constexpr std::size_t kWorkAheadSamples = kInkChunkSegments;

  explicit Pipeline(DaemonState& state)
      : state_(state),
        grouping_(
            state, [this] { job_started(); }, [this] { job_done(); },
            [this](const std::string& device_id, std::uint64_t stroke_id, const v1::PolygonSet& ink,
                   const PenSettings& settings) {
              maybe_deconstruct(device_id, stroke_id, ink, settings);
            }) {}

  void device_attached(const DeviceDescriptor& device) override;
  void device_detached(const std::string& device_id) override;
  void stroke_started(const std::string& device_id, std::uint64_t stroke_id) override;
  void sample(const std::string& device_id, std::uint64_t stroke_id,
              const PenSample& sample) override;
  void stroke_finished(const std::string& device_id, Stroke stroke) override;
  [[nodiscard]] bool wants_raw_reports() const override { return state_.hub.wants_raw_reports(); }
  void raw_report(const std::string& device_id, std::span<const std::uint8_t> bytes,
                  std::int64_t time_us) override {
    publish_raw_report(state_.hub, device_id, bytes, time_us); // straight through, like samples
  }

  // Returns once every job handed to the workers (analyses, previews) has been published.
  void wait_idle();

 private:
  // The stroke a device is drawing, kept only when there is an analyzer (for previews). Its
  // samples are kept in sealed, shared blocks plus an open tail, so that asking for a preview
  // costs the reader thread a few pointer copies, never a copy of the whole stroke.
  struct Drawing {
    std::uint64_t stroke_id = 0;
    TabletInfo tablet;
    std::vector<std::shared_ptr<const std::vector<PenSample>>> sealed;
    std::vector<PenSample> open;
    std::size_t samples = 0;
    std::chrono::steady_clock::time_point last_preview{};
    bool preview_running = false;
    // Work ahead (StrokeAnalyzer::work_ahead): samples it was last asked with, and one at a time.
    std::size_t ahead_asked = 0;
    bool ahead_running = false;
    // Set when the stroke ends: its preview job (if any) stops.
    std::shared_ptr<std::atomic<bool>> ended = std::make_shared<std::atomic<bool>>(false);
    // Hold to snap (snap_trigger hold or both, and an analyzer that groups).
    std::optional<HoldDetector> detector;
    std::shared_ptr<HoldState> hold; // the stroke's hold being snapped, or snapped
    bool hold_only = false;          // snap_trigger = hold
    double hold_radius_mm = 0;
    FollowGate gate; // the shape's updates as it follows the pen after the hold

    void restart(std::uint64_t id, const TabletInfo& t) {
      stroke_id = id;
      tablet = t;
      sealed.clear();
      open.clear();
      samples = 0;
      ahead_asked = 0;
      detector.reset();
      hold.reset();
      hold_only = false;
      gate = {};
    }
    // The samples so far in one block (the open tail sealed); returns every block.
    const std::vector<std::shared_ptr<const std::vector<PenSample>>>& seal() {
      if (!open.empty()) {
        sealed.push_back(std::make_shared<const std::vector<PenSample>>(std::exchange(open, {})));
      }
      return sealed;
    }
  };
  // What a sample of a stroke with hold to snap asks for, done once mutex_ is released.
  struct HoldWork {
    std::optional<v1::LiveEvent> follow; // a FOLLOW update to publish
    std::optional<Stroke> snap;          // the stroke so far to snap (the hold is satisfied)
    std::optional<Stroke> prepare;       // the same, to recognize ahead (the pen settled)
    std::shared_ptr<HoldState> hold;
  };
  HoldWork on_hold_sample(const std::string& device_id, Drawing& drawing, const PenSample& sample);
  static Stroke drawn_before_rest(Drawing& drawing);
  void job_started();
  void job_done();
  void maybe_preview(const std::string& device_id, Drawing& drawing);
  void maybe_work_ahead(const std::string& device_id, Drawing& drawing);
  void maybe_deconstruct(const std::string& device_id, std::uint64_t stroke_id,
                         const v1::PolygonSet& ink, const PenSettings& settings);

  DaemonState& state_;
  std::mutex mutex_;
  std::condition_variable idle_;
  std::size_t in_flight_ = 0;
  std::map<std::string, Drawing> drawing_; // by device id, guarded by mutex_
  LiveGrouping grouping_; // each device's strokes grouped in order (when the analyzer groups)
};

} // namespace penshape::daemon
