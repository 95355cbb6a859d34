#pragma once
// The pipeline's sequenced stage for live strokes: each tablet's finished strokes are grouped
// with its recent strokes (the analyzer's StrokeGroupSession, core's StrokeGrouper). Strokes of
// all devices are analysed on the stroke lane, but one device's strokes run one at a time and
// in drawing order (a strand per device: a job on the stroke lane that takes the device's
// queued strokes until none is left), since a grouping must see them in order. A stroke's ink
// polygon and shape are computed in that one step, so grouping adds no hand-over between workers
// to the pen-up -> shape path.
//
// Each answer is published as StrokeFinished then ShapeRecognized with its shape_id, the ids of
// the strokes whose ink it replaces and the shape_ids (and LiveEvent sequences) of the earlier
// answers it supersedes. When the answer read no ink polygon (nothing snapped alone, or a union
// certified on the strokes' paths) and Q is not built yet, the shape goes first and StrokeFinished
// follows as soon as Q exists; should Q then fail, the shape stands and StrokeFinished carries the
// error (not_analysed) without an ink polygon. While previews are wanted, a copy of each device's
// grouping is kept after every stroke, so a preview can add the stroke in progress to a copy of its
// own (on the preview lane, without touching the strand's state).
//
// Hold to snap runs on the same strand: the stroke so far of a hold is queued after the strokes
// finished before it and recognized with the grouping (hold_snap.hpp), its HOLD shape published at
// once; at pen-up the stroke's final shape (RELEASE) replaces its analysis (live.proto's HoldSnap).
#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "daemon_state.hpp"
#include "group_history.hpp"
#include "hold_snap.hpp"
#include "hold_state.hpp"
#include "penshape/v1/live.pb.h"

namespace penshape::daemon {

class LiveGrouping {
 public:
  // Told after a stroke's shape is published, with its ink polygon (the deconstruction follows).
  using ShapePublished = std::function<void(const std::string& device_id, std::uint64_t stroke_id,
                                            const v1::PolygonSet& ink, const PenSettings&)>;
  // `job_started` / `job_done` account the strand jobs (Pipeline::wait_idle).
  LiveGrouping(DaemonState& state, std::function<void()> job_started,
               std::function<void()> job_done, ShapePublished published)
      : state_(state),
        job_started_(std::move(job_started)),
        job_done_(std::move(job_done)),
        published_(std::move(published)) {}

  // The analyzer groups strokes (else each live stroke is analysed alone, concurrently).
  bool groups();
  // Queues a finished stroke for its device's strand (call only when groups()). `hold`: the
  // stroke's hold (hold to snap), if it had one: when it snapped, pen-up publishes its final shape
  // (RELEASE) instead of analysing the stroke. `hold_only` (snap_trigger = hold): a stroke whose
  // hold snapped nothing is still grouped, but gets no ShapeRecognized.
  void finish(const std::string& device_id, Stroke stroke,
              std::shared_ptr<HoldState> hold = nullptr, bool hold_only = false);
  // Queues the stroke so far of a hold (hold to snap) for its device's strand, after the strokes
  // finished before it: its grouped, certified shape is published at once (HOLD) and `hold`
  // told what it snapped (HoldState::Phase).
  void hold(const std::string& device_id, Stroke partial, std::shared_ptr<HoldState> hold);
  // Queues the stroke drawn before the pen came to rest (it has rested a while, not yet a hold):
  // the strand recognizes it ahead, unpublished, and a hold that follows on the same rest, with
  // nothing else run on the strand between, publishes that answer at once. A pen-up or another
  // rest queued meanwhile cancels the work (it never delays a pen-up by more than a check).
  void prepare_hold(const std::string& device_id, Stroke partial);
  // The device is gone: its grouping is forgotten (unless its strand still runs).
  void forget_device(const std::string& device_id);
  // The certified group the stroke in progress would complete with its device's recent strokes
  // if the pen lifted now, or nothing. Called on the preview lane.
  std::optional<v1::PreviewGroup> preview_group(const std::string& device_id, const Stroke& partial,
                                                const CancelHook& cancel);

 private:
  struct Pending {
    Stroke stroke;
    std::chrono::steady_clock::time_point submitted;
    std::shared_ptr<HoldState> hold; // the stroke's hold, if any
    bool is_hold = false;            // the stroke so far of `hold` (else a finished stroke)
    bool hold_only = false;          // snap_trigger = hold
    bool is_prepare = false;         // the stroke before a rest, to recognize ahead
  };
  // A rest's stroke recognized ahead (prepare_hold), for the hold that may follow.
  struct PreparedHold {
    std::uint64_t stroke_id = 0;
    std::size_t samples = 0;
    std::int64_t last_time_us = 0;
    std::uint64_t epoch = 0; // the grouping's (GroupHistory::epoch)
    HoldTrial trial;
  };
  struct Lane {
    std::mutex mutex;
    std::deque<Pending> queue; // guarded by mutex
    bool running = false;      // a strand job runs (guarded by mutex)
    // The device's grouping, used by the running strand job only. It keeps only the strokes the
    // grouping window can reach, so a long session's memory (and a preview's copy) stay bounded.
    GroupHistory history;
    std::shared_ptr<const GroupHistory> snapshot; // for previews, guarded by mutex
    std::optional<PreparedHold> prepared;         // used by the running strand job only
  };

  void enqueue(const std::string& device_id, Pending pending);
  void run_strand(const std::shared_ptr<Lane>& lane, const std::string& device_id);
  void process(Lane& lane, const std::string& device_id, const Pending& pending);
  void analyse(Lane& lane, const std::string& device_id, const Pending& pending);
  void prepare(Lane& lane, const std::string& device_id, const Pending& pending);
  void snap_hold(Lane& lane, const std::string& device_id, const Pending& pending,
                 std::optional<PreparedHold> prepared);
  static void wait_hold_ink(HoldState& hold);
  void release(Lane& lane, const std::string& device_id, const Pending& pending);
  void publish_finished(const std::string& device_id, const Stroke& stroke,
                        const v1::PolygonSet& ink);
  // Publishes the ShapeRecognized (unless `publish_shape` is false) and remembers the answer.
  void publish(const std::string& device_id, const Stroke& stroke, GroupedStrokeAnalysis& result,
               const v1::Timings& timings, GroupHistory& history, bool publish_shape);

  DaemonState& state_;
  std::function<void()> job_started_;
  std::function<void()> job_done_;
  ShapePublished published_;
  std::atomic<int> groups_{-1}; // the analyzer groups: -1 not known yet, 0 no, 1 yes
  std::mutex mutex_;            // guards lanes_
  std::map<std::string, std::shared_ptr<Lane>> lanes_; // by device id
};

} // namespace penshape::daemon
