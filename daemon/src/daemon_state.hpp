#pragma once
// What the services share: limits, the worker pool, the hub, the settings, the pluggable parts.
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "group_history.hpp"
#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/grouping_settings.hpp"
#include "penshape/daemon/limits.hpp"
#include "penshape/daemon/pen_settings.hpp"
#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"
#include "penshape/daemon/worker_pool.hpp"

namespace penshape::daemon {

// The devices attached now, as the pipeline saw them attach.
class DeviceRegistry {
 public:
  void add(const DeviceDescriptor& device);
  void remove(const std::string& id);
  [[nodiscard]] std::vector<DeviceDescriptor> list() const;
  // The device's tablet and settings key; false when unknown.
  bool find(const std::string& id, DeviceDescriptor* out) const;

 private:
  mutable std::mutex mutex_;
  std::map<std::string, DeviceDescriptor> devices_;
};

// Work runs in three lanes so that what a user waits for is never queued behind what nobody
// waits for: the pen-up -> shape budget is 16 ms and a report must reach subscribers within 1 ms,
// on a machine that may have 2 cores.
//   stroke_pool   stroke analyses (live strokes, SubmitStroke, StreamSamples, Recognize):
//                 interactive priority, just below the readers and gRPC threads;
//   pool          geometry RPCs (Deconstruct, searches): batch priority, so a long search
//                 shares the cores but yields them to readers, gRPC and stroke analyses;
//   preview_pool  live previews while the pen moves: idle priority, a hint that may come late.
struct DaemonState {
  DaemonState(const Limits& l, const PenSettings& defaults,
              std::map<std::string, PenSettingsUpdate> per_device,
              GroupingConfig live_grouping = {})
      : limits(l),
        pool(l.worker_threads, l.worker_queue_jobs, WorkerPriority::kBatch),
        stroke_pool(l.stroke_worker_threads, l.worker_queue_jobs, WorkerPriority::kInteractive),
        preview_pool(1, kPreviewQueueJobs, WorkerPriority::kIdle),
        hub(l.max_subscribers, l.max_raw_report_subscribers),
        settings(defaults, std::move(per_device)),
        grouping(live_grouping),
        group_keys(l.max_group_keys) {}

  // Previews in flight are at most one per device (pipeline.hpp); more queued would be stale.
  static constexpr std::size_t kPreviewQueueJobs = 16;

  const Limits limits;
  WorkerPool pool;
  WorkerPool stroke_pool;
  WorkerPool preview_pool;
  ShapeHub hub;
  SettingsStore settings;
  GroupingStore grouping; // live strokes' grouping window and tidy-up (Config RPC, config file)
  DeviceRegistry devices;
  std::shared_ptr<GeometryBackend> geometry; // null: Deconstruct is UNIMPLEMENTED
  std::shared_ptr<StrokeAnalyzer> analyzer;  // null: no ink polygons or shapes
  // Ids for strokes the daemon numbers itself (SubmitStroke, StreamSamples), from 2^63 up so
  // they never meet a source's ids.
  std::atomic<std::uint64_t> next_stroke_id{std::uint64_t{1} << 63U};
  // The groupings of SubmitStroke's group_keys (at most limits.max_group_keys).
  GroupKeys group_keys;
  // Ids of grouped answers (ShapeRecognized.shape_id), unique per run over every grouping.
  std::atomic<std::uint64_t> next_shape_id{0};
};

void to_proto(const DeviceDescriptor& device, v1::DeviceInfo* out);

// The settings for a tablet model (its Config key "vvvv:pppp"), or the defaults.
PenSettings settings_for(const DaemonState& state, const TabletInfo& tablet);

// Publishes a stroke's StrokeFinished (with the analysis when there is one) and ShapeRecognized.
void publish_stroke(ShapeHub& hub, const std::string& device_id, const Stroke& stroke,
                    const StrokeAnalysis* analysis, const std::string& not_analysed,
                    const v1::Timings& timings);
// The same; `decorate` completes the ShapeRecognized (its grouping fields) before it is
// published. Returns that event's sequence (0 when none was published).
std::uint64_t publish_stroke(ShapeHub& hub, const std::string& device_id, const Stroke& stroke,
                             const StrokeAnalysis* analysis, const std::string& not_analysed,
                             const v1::Timings& timings,
                             const std::function<void(v1::ShapeRecognized&)>& decorate);

// A stroke analysis's side jobs (its ink polygon, built while the path is fitted) on the other
// workers of `pool`, the stroke lane: a job no worker takes in time is done by the analysis itself.
InkOffload ink_offload(WorkerPool& pool);

// Publishes one raw input report (RawReport). The caller checks hub.wants_raw_reports() first.
void publish_raw_report(ShapeHub& hub, const std::string& device_id,
                        std::span<const std::uint8_t> bytes, std::int64_t time_us);

// A penshape.v1 service's implementation: its generated gRPC Service, on the daemon's state.
template <typename GeneratedService>
class StateService : public GeneratedService {
 public:
  explicit StateService(DaemonState& state) : state_(state) {}

 protected:
  DaemonState& state_;
};

} // namespace penshape::daemon
