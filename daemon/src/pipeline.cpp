#include "pipeline.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

#include "call_runner.hpp"
#include "geometry_service.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "thread_scheduling.hpp"

namespace penshape::daemon {

void Pipeline::device_attached(const DeviceDescriptor& device) {
  state_.devices.add(device);
  v1::LiveEvent event;
  event.set_device_id(device.id);
  to_proto(device, event.mutable_device_attached()->mutable_device());
  state_.hub.publish(std::move(event));
}

void Pipeline::device_detached(const std::string& device_id) {
  state_.devices.remove(device_id);
  {
    std::lock_guard lock(mutex_);
    const auto it = drawing_.find(device_id);
    if (it != drawing_.end() && !it->second.preview_running) drawing_.erase(it);
  }
  grouping_.forget_device(device_id);
  v1::LiveEvent event;
  event.set_device_id(device_id);
  event.mutable_device_detached()->set_device_id(device_id);
  state_.hub.publish(std::move(event));
}

void Pipeline::stroke_started(const std::string& device_id, std::uint64_t stroke_id) {
  v1::LiveEvent event;
  event.set_device_id(device_id);
  v1::StrokeStarted* started = event.mutable_stroke_started();
  started->set_stroke_id(stroke_id);
  DeviceDescriptor device;
  const bool known = state_.devices.find(device_id, &device);
  if (known) to_proto(device.tablet, started->mutable_tablet());
  state_.hub.publish(std::move(event));
  if (state_.analyzer) {
    std::lock_guard lock(mutex_);
    Drawing& drawing = drawing_[device_id];
    drawing.ended->store(true); // a stroke that never finished (device reset): its preview stops
    drawing.ended = std::make_shared<std::atomic<bool>>(false);
    drawing.restart(stroke_id, known ? device.tablet : TabletInfo{});
    const PenSettings settings = settings_for(state_, drawing.tablet);
    if (settings.snap_trigger != SnapTrigger::kPenUp && grouping_.groups()) {
      drawing.detector.emplace(settings, drawing.tablet);
      drawing.hold_only = settings.snap_trigger == SnapTrigger::kHold;
      drawing.hold_radius_mm = settings.hold_radius_mm;
    }
  }
}

namespace {

// The samples of blocks, as one stroke.
Stroke assemble(std::uint64_t id, const TabletInfo& tablet,
                const std::vector<std::shared_ptr<const std::vector<PenSample>>>& blocks,
                std::size_t count) {
  Stroke out;
  out.id = id;
  out.tablet = tablet;
  out.samples.reserve(count);
  for (const auto& block : blocks)
    out.samples.insert(out.samples.end(), block->begin(), block->end());
  return out;
}

} // namespace

void Pipeline::sample(const std::string& device_id, std::uint64_t stroke_id,
                      const PenSample& sample) {
  request_short_slice_once(); // the reader thread: a sample must reach subscribers within 1 ms
  v1::LiveEvent event;
  event.set_device_id(device_id);
  v1::SamplesBatch* batch = event.mutable_samples();
  batch->set_stroke_id(stroke_id);
  to_proto(sample, batch->add_samples());
  state_.hub.publish(std::move(event));
  if (!state_.analyzer || stroke_id == 0) return;
  HoldWork work;
  {
    std::lock_guard lock(mutex_);
    const auto it = drawing_.find(device_id);
    if (it == drawing_.end() || it->second.stroke_id != stroke_id) return;
    if (it->second.samples >= state_.limits.max_stroke_samples) return;
    it->second.open.push_back(sample);
    ++it->second.samples;
    maybe_preview(device_id, it->second);
    maybe_work_ahead(device_id, it->second);
    work = on_hold_sample(device_id, it->second, sample);
  }
  // Outside mutex_: the strand's accounting takes it (job_started).
  if (work.prepare) grouping_.prepare_hold(device_id, std::move(*work.prepare));
  if (work.snap) grouping_.hold(device_id, std::move(*work.snap), std::move(work.hold));
  if (work.follow) state_.hub.publish(std::move(*work.follow));
}

// Called with mutex_ held: the stroke drawn before the pen came to rest (its tremor while it
// rests is not drawing).
Stroke Pipeline::drawn_before_rest(Drawing& drawing) {
  Stroke drawn = assemble(drawing.stroke_id, drawing.tablet, drawing.seal(), drawing.samples);
  const std::int64_t rest = drawing.detector->held_since_us();
  while (drawn.samples.size() > 2 && drawn.samples.back().time_us > rest) drawn.samples.pop_back();
  return drawn;
}

// Called with mutex_ held, for each sample kept. Before the hold: is it satisfied now? After a
// snapped hold: the shape follows the pen once it leaves the hold radius, one update per
// kFollowIntervalUs of the tablet's clock at most.
Pipeline::HoldWork Pipeline::on_hold_sample(const std::string& device_id, Drawing& drawing,
                                            const PenSample& sample) {
  HoldWork work;
  if (!drawing.detector || !sample.tip) return work;
  const PointMm tip = sample_mm(sample, drawing.tablet);
  if (!drawing.hold) {
    if (!drawing.detector->add(sample)) {
      if (drawing.detector->settled()) work.prepare = drawn_before_rest(drawing);
      return work;
    }
    drawing.hold = std::make_shared<HoldState>();
    drawing.hold->time_us = sample.time_us;
    drawing.hold->point = tip;
    drawing.hold->radius_mm = drawing.hold_radius_mm;
    drawing.gate = {};
    work.snap = drawn_before_rest(drawing);
    drawing.hold->samples = work.snap->samples.size();
    work.hold = drawing.hold;
    return work;
  }
  const std::shared_ptr<HoldState> held = drawing.hold; // outlives the reset below
  HoldState& hold = *held;
  drawing.gate.see(hold, tip);
  {
    std::lock_guard lock(hold.mutex);
    if (hold.phase == HoldState::Phase::kNothing) { // nothing snapped: the stroke goes on
      drawing.hold.reset();
      drawing.detector->add(sample);
      return work;
    }
    if (hold.phase == HoldState::Phase::kPending) return work;
  } // snapped: the hold's fields no longer change
  if (!drawing.gate.due(sample.time_us)) return work;
  const auto started = std::chrono::steady_clock::now();
  work.follow = hold_event(device_id, drawing.stroke_id, hold, {true, tip, sample.time_us},
                           v1::SHAPE_TRIGGER_FOLLOW);
  work.follow->mutable_shape()->mutable_timings()->set_compute_us(
      static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                     std::chrono::steady_clock::now() - started)
                                     .count()));
  return work;
}

// Called with mutex_ held.
void Pipeline::maybe_preview(const std::string& device_id, Drawing& drawing) {
  const auto now = std::chrono::steady_clock::now();
  if (drawing.preview_running || now - drawing.last_preview < kPreviewInterval) return;
  if (!state_.hub.wants_previews()) return;
  drawing.preview_running = true;
  drawing.last_preview = now;
  const PenSettings settings = settings_for(state_, drawing.tablet);
  auto job = [this, device_id, id = drawing.stroke_id, tablet = drawing.tablet,
              blocks = drawing.seal(), count = drawing.samples,
              settings](const StopCondition& stop) {
    try {
      const Stroke partial = assemble(id, tablet, blocks, count); // here, on the preview lane
      std::vector<v1::Shape> candidates =
          state_.analyzer->preview(partial, settings, cancel_hook(stop));
      // The group the stroke would complete with the device's recent strokes (certified); not
      // started once the pen has lifted.
      std::optional<v1::PreviewGroup> group;
      if (!stop.cancelled()) group = grouping_.preview_group(device_id, partial, cancel_hook(stop));
      // Once the pen has lifted, the stroke's shape supersedes any preview: publishing it would
      // only compete with that shape for the subscribers' threads.
      if ((!candidates.empty() || group) && !stop.cancelled()) {
        v1::LiveEvent event;
        event.set_device_id(device_id);
        v1::PreviewCandidates* preview = event.mutable_preview();
        preview->set_stroke_id(partial.id);
        for (auto& c : candidates) *preview->add_candidates() = std::move(c);
        if (group) preview->mutable_group()->Swap(&*group);
        state_.hub.publish(std::move(event));
      }
    } catch (...) {
      // A preview is a hint: a failed one is skipped, the finished stroke still gets its shape.
    }
    {
      std::lock_guard lock(mutex_);
      const auto it = drawing_.find(device_id);
      if (it != drawing_.end()) it->second.preview_running = false;
    }
    job_done();
  };
  ++in_flight_;
  // A preview older than a few frames is useless: it stops at its deadline, or when its stroke
  // ends.
  const StopCondition stop(now + 4 * kPreviewInterval,
                           [ended = drawing.ended] { return ended->load(); });
  if (!state_.preview_pool.submit(std::move(job), stop)) {
    drawing.preview_running = false;
    if (--in_flight_ == 0) idle_.notify_all();
  }
}

// Called with mutex_ held: a grouped stroke's ink polygon is built on a stroke worker while the
// pen is down, a chunk at a time (the pen-up then reuses it).
void Pipeline::maybe_work_ahead(const std::string& device_id, Drawing& drawing) {
  if (drawing.ahead_running || drawing.samples < drawing.ahead_asked + kWorkAheadSamples) return;
  if (!grouping_.groups()) return; // analyze() alone builds Q at once
  drawing.ahead_running = true;
  drawing.ahead_asked = drawing.samples;
  auto job = [this, device_id, id = drawing.stroke_id, tablet = drawing.tablet,
              blocks = drawing.seal(), count = drawing.samples,
              settings = settings_for(state_, drawing.tablet)](const StopCondition& stop) {
    try {
      if (!stop.cancelled()) { // a stroke already ended: its pen-up took over
        state_.analyzer->work_ahead(assemble(id, tablet, blocks, count), settings,
                                    cancel_hook(stop));
      }
    } catch (...) {
      // Work ahead is optional: the pen-up does whatever is missing (and reports its errors).
    }
    {
      std::lock_guard lock(mutex_);
      const auto it = drawing_.find(device_id);
      if (it != drawing_.end() && it->second.stroke_id == id) it->second.ahead_running = false;
    }
    job_done();
  };
  ++in_flight_;
  // It stops once its stroke ends: the pen-up takes over what is left.
  const StopCondition stop(
      std::chrono::steady_clock::now() + std::chrono::seconds(state_.limits.max_call_seconds),
      [ended = drawing.ended] { return ended->load(); });
  if (!state_.stroke_pool.submit(std::move(job), stop)) {
    drawing.ahead_running = false;
    if (--in_flight_ == 0) idle_.notify_all();
  }
}

void Pipeline::stroke_finished(const std::string& device_id, Stroke stroke) {
  std::shared_ptr<HoldState> hold; // hold to snap: the stroke's hold, if any
  bool hold_only = false;
  if (state_.analyzer) {
    std::lock_guard lock(mutex_);
    const auto it = drawing_.find(device_id);
    if (it != drawing_.end() && it->second.stroke_id == stroke.id) {
      hold = it->second.hold;
      hold_only = it->second.hold_only;
    }
    if (it != drawing_.end()) it->second.ended->store(true);
    if (it != drawing_.end() && !it->second.preview_running) {
      drawing_.erase(it);
    } else if (it != drawing_.end()) {
      // Its preview job still runs (and stops soon): drop the samples, keep the entry.
      it->second.restart(0, TabletInfo{});
    }
  }
  if (!state_.analyzer) {
    publish_stroke(state_.hub, device_id, stroke, nullptr,
                   "this build has no stroke analyzer (ink polygon and recognizer)", {});
    return;
  }
  if (grouping_.groups()) { // grouped in order on its device's strand
    grouping_.finish(device_id, std::move(stroke), std::move(hold), hold_only);
    return;
  }
  const PenSettings settings = settings_for(state_, stroke.tablet);
  const auto submitted = std::chrono::steady_clock::now();
  // The job owns its copy of the stroke; the reader thread returns at once.
  auto job = [this, device_id, stroke, settings, submitted](const StopCondition& stop) {
    using std::chrono::duration_cast;
    using std::chrono::microseconds;
    const auto started = std::chrono::steady_clock::now();
    v1::Timings timings;
    timings.set_queued_us(
        static_cast<std::uint64_t>(duration_cast<microseconds>(started - submitted).count()));
    try {
      const StrokeAnalysis analysis = state_.analyzer->analyze(stroke, settings, cancel_hook(stop));
      const auto now = std::chrono::steady_clock::now();
      timings.set_compute_us(
          static_cast<std::uint64_t>(duration_cast<microseconds>(now - started).count()));
      timings.set_total_us(
          static_cast<std::uint64_t>(duration_cast<microseconds>(now - submitted).count()));
      publish_stroke(state_.hub, device_id, stroke, &analysis, "", timings);
      maybe_deconstruct(device_id, stroke.id, analysis.ink_polygon, settings);
    } catch (const std::exception& e) {
      publish_stroke(state_.hub, device_id, stroke, nullptr,
                     std::string("analysis failed: ") + e.what(), timings);
    } catch (...) {
      publish_stroke(state_.hub, device_id, stroke, nullptr, "analysis failed", timings);
    }
    job_done();
  };
  const StopCondition stop(
      std::chrono::steady_clock::now() + std::chrono::seconds(state_.limits.max_call_seconds), {});
  job_started();
  if (!state_.stroke_pool.submit(std::move(job), stop)) {
    job_done();
    // Never block the reader and never lose the stroke: publish it without its analysis.
    publish_stroke(state_.hub, device_id, stroke, nullptr,
                   "the geometry queue was full; the stroke was not analysed", {});
  }
}

// eps = tolerance_fraction * r, delta = precision_fraction * eps (pen_settings.hpp), exact.
DeconstructParams deconstruct_params_for(const PenSettings& settings) {
  DeconstructParams params;
  params.radius = exact(settings.pen_radius_mm);
  params.tolerance = params.radius * exact(settings.tolerance_fraction);
  params.precision = params.tolerance * exact(settings.precision_fraction);
  params.engine = EngineKind::kFast;
  return params;
}

// Called on the stroke lane once the stroke's shape is published: the deconstruction runs on the
// geometry lane (batch priority), so it never delays a shape.
void Pipeline::maybe_deconstruct(const std::string& device_id, std::uint64_t stroke_id,
                                 const v1::PolygonSet& ink, const PenSettings& settings) {
  if (!state_.hub.wants_deconstructions()) return;
  auto publish = [this, device_id, stroke_id](v1::DeconstructResponse* result,
                                              const std::string& not_deconstructed) {
    v1::LiveEvent event;
    event.set_device_id(device_id);
    v1::StrokeDeconstructed* d = event.mutable_deconstructed();
    d->set_stroke_id(stroke_id);
    if (result != nullptr) d->mutable_result()->Swap(result);
    d->set_not_deconstructed(not_deconstructed);
    state_.hub.publish(std::move(event));
  };
  if (!state_.geometry) return publish(nullptr, "this build has no deconstruction engine");
  if (ink.polygons_size() == 0) return publish(nullptr, "the stroke has no ink polygon");
  const auto submitted = std::chrono::steady_clock::now();
  auto job = [this, ink, settings, submitted, publish](const StopCondition& stop) {
    using std::chrono::duration_cast;
    using std::chrono::microseconds;
    const auto started = std::chrono::steady_clock::now();
    v1::DeconstructResponse result;
    std::string why;
    try {
      const PolygonSet q = polygon_set_from_proto(ink, "ink_polygon", state_.limits);
      deconstruct_into(*state_.geometry, q, deconstruct_params_for(settings),
                       {.simplify = true, .include_offset = true, .extras_if_available = true},
                       cancel_hook(stop), core_limits(state_.limits), &result);
      const auto now = std::chrono::steady_clock::now();
      v1::Timings* t = result.mutable_timings();
      t->set_queued_us(
          static_cast<std::uint64_t>(duration_cast<microseconds>(started - submitted).count()));
      t->set_compute_us(
          static_cast<std::uint64_t>(duration_cast<microseconds>(now - started).count()));
      t->set_total_us(
          static_cast<std::uint64_t>(duration_cast<microseconds>(now - submitted).count()));
    } catch (const std::exception& e) {
      why = stop.deadline_passed() ? "the deconstruction passed its deadline (max_call_seconds)"
                                   : std::string("deconstruction failed: ") + e.what();
    }
    publish(why.empty() ? &result : nullptr, why);
    job_done();
  };
  const StopCondition stop(
      std::chrono::steady_clock::now() + std::chrono::seconds(state_.limits.max_call_seconds), {});
  job_started();
  if (!state_.pool.submit(std::move(job), stop)) {
    job_done();
    publish(nullptr, "the geometry queue was full; the stroke was not deconstructed");
  }
}

void Pipeline::job_started() {
  std::lock_guard lock(mutex_);
  ++in_flight_;
}

void Pipeline::job_done() {
  std::lock_guard lock(mutex_);
  if (--in_flight_ == 0) idle_.notify_all();
}

void Pipeline::wait_idle() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return in_flight_ == 0; });
}

} // namespace penshape::daemon
