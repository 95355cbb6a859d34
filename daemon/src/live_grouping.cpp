// Per-device strands grouping live strokes, and group previews (live_grouping.hpp).
#include "live_grouping.hpp"

#include <chrono>
#include <utility>

#include "call_runner.hpp"
#include "penshape/daemon/proto_convert.hpp"

namespace penshape::daemon {
namespace {

std::uint64_t micros(std::chrono::steady_clock::duration d) {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(d).count());
}

} // namespace

bool LiveGrouping::groups() {
  int known = groups_.load();
  if (known < 0) {
    known = state_.analyzer && state_.analyzer->group_session({}, {}) ? 1 : 0;
    groups_.store(known);
  }
  return known == 1;
}

void LiveGrouping::finish(const std::string& device_id, Stroke stroke,
                          std::shared_ptr<HoldState> hold, bool hold_only) {
  enqueue(device_id,
          {std::move(stroke), std::chrono::steady_clock::now(), std::move(hold), false, hold_only});
}

void LiveGrouping::hold(const std::string& device_id, Stroke partial,
                        std::shared_ptr<HoldState> hold) {
  enqueue(device_id,
          {std::move(partial), std::chrono::steady_clock::now(), std::move(hold), true, false});
}

void LiveGrouping::prepare_hold(const std::string& device_id, Stroke partial) {
  Pending pending{std::move(partial), std::chrono::steady_clock::now(), nullptr, false, false};
  pending.is_prepare = true;
  enqueue(device_id, std::move(pending));
}

void LiveGrouping::enqueue(const std::string& device_id, Pending pending) {
  std::shared_ptr<Lane> lane;
  {
    std::lock_guard lock(mutex_);
    auto& slot = lanes_[device_id];
    if (!slot) slot = std::make_shared<Lane>();
    lane = slot;
  }
  {
    std::lock_guard lock(lane->mutex);
    lane->queue.push_back(std::move(pending));
    if (lane->running) return; // the strand takes it after the strokes before it
    lane->running = true;
  }
  job_started_();
  if (state_.stroke_pool.submit([this, lane, device_id](const StopCondition& /*unused*/) {
        run_strand(lane, device_id);
      })) {
    return;
  }
  job_done_();
  // Never block the reader and never lose a stroke: publish them without their analysis.
  std::deque<Pending> refused;
  {
    std::lock_guard lock(lane->mutex);
    refused.swap(lane->queue);
    lane->running = false;
  }
  for (const Pending& p : refused) {
    if (p.is_prepare) continue; // work ahead only
    if (p.is_hold) {
      std::lock_guard hold_lock(p.hold->mutex);
      p.hold->phase = HoldState::Phase::kNothing; // not snapped: the stroke goes on
      continue;
    }
    publish_stroke(state_.hub, device_id, p.stroke, nullptr,
                   "the geometry queue was full; the stroke was not analysed", {});
  }
}

void LiveGrouping::run_strand(const std::shared_ptr<Lane>& lane, const std::string& device_id) {
  for (;;) {
    Pending next;
    {
      std::lock_guard lock(lane->mutex);
      if (lane->queue.empty()) {
        lane->running = false;
        break;
      }
      next = std::move(lane->queue.front());
      lane->queue.pop_front();
    }
    process(*lane, device_id, next);
  }
  job_done_();
}

void LiveGrouping::process(Lane& lane, const std::string& device_id, const Pending& pending) {
  bool snapped_hold = false;
  if (pending.hold) {
    std::lock_guard lock(pending.hold->mutex);
    snapped_hold = pending.hold->phase == HoldState::Phase::kSnapped;
  }
  if (pending.is_prepare) { // work ahead: publishes nothing, changes no grouping
    prepare(lane, device_id, pending);
    return;
  }
  // Anything but the hold it was prepared for changes the grouping it was prepared on.
  std::optional<PreparedHold> prepared = std::exchange(lane.prepared, std::nullopt);
  if (pending.is_hold) {
    snap_hold(lane, device_id, pending, std::move(prepared));
  } else if (snapped_hold) {
    release(lane, device_id, pending);
  } else {
    analyse(lane, device_id, pending);
  }
  // After the shape is out: the copy a preview of the next stroke starts from.
  std::shared_ptr<const GroupHistory> snapshot;
  if (state_.hub.wants_previews()) {
    snapshot = std::make_shared<const GroupHistory>(lane.history.copy());
  }
  std::lock_guard lock(lane.mutex);
  lane.snapshot = std::move(snapshot);
}

void LiveGrouping::analyse(Lane& lane, const std::string& device_id, const Pending& pending) {
  const auto started = std::chrono::steady_clock::now();
  v1::Timings timings;
  timings.set_queued_us(micros(started - pending.submitted));
  const Stroke& stroke = pending.stroke;
  GroupHistory& h = lane.history;
  const PenSettings settings = settings_for(state_, stroke.tablet);
  // New settings (Config RPC): start afresh with the values now in force.
  h.ensure(*state_.analyzer, settings, state_.grouping.get());
  const StopCondition stop(started + std::chrono::seconds(state_.limits.max_call_seconds), {});
  InkOffload offload = ink_offload(state_.stroke_pool);
  offload.shape_first = true; // an answer that read no Q does not wait for it
  bool shape_out = false;
  try {
    GroupedStrokeAnalysis result = h.add(stroke, true, cancel_hook(stop), offload);
    const auto now = std::chrono::steady_clock::now();
    timings.set_compute_us(micros(now - started));
    timings.set_total_us(micros(now - pending.submitted));
    const bool ink_later = static_cast<bool>(result.ink_later);
    if (!ink_later) publish_finished(device_id, stroke, result.analysis.ink_polygon);
    publish(device_id, stroke, result, timings, h, !pending.hold_only);
    shape_out = true;
    // The shape did not read Q: StrokeFinished follows as soon as Q exists. Should Q fail now,
    // the shape stands (certified on the path) and StrokeFinished carries the error instead.
    if (ink_later) {
      result.wait_ink();
      publish_finished(device_id, stroke, result.analysis.ink_polygon);
    }
    if (published_) published_(device_id, stroke.id, result.analysis.ink_polygon, settings);
  } catch (const std::exception& e) {
    const char* what = shape_out ? "ink polygon failed: " : "analysis failed: ";
    publish_stroke(state_.hub, device_id, stroke, nullptr, std::string(what) + e.what(), timings);
  } catch (...) {
    publish_stroke(state_.hub, device_id, stroke, nullptr,
                   shape_out ? "ink polygon failed" : "analysis failed", timings);
  }
}

// The stroke so far is added to a copy of the grouping; only a certified shape makes the copy
// the device's grouping (the stroke then counts as drawn up to the hold), else nothing changed.
// The hold's stroke recognized ahead, on a copy of the grouping; kept in lane.prepared for the
// hold. Given up (nothing kept) when a pen-up or another rest is queued behind it.
void LiveGrouping::prepare(Lane& lane, const std::string& /*device_id*/, const Pending& pending) {
  lane.prepared.reset();
  GroupHistory& h = lane.history;
  const Stroke& partial = pending.stroke;
  if (partial.samples.empty()) return;
  if (!h.ensure(*state_.analyzer, settings_for(state_, partial.tablet), state_.grouping.get())) {
    return;
  }
  const auto started = std::chrono::steady_clock::now();
  const StopCondition stop(started + std::chrono::seconds(state_.limits.max_call_seconds), {});
  const CancelHook stopped = cancel_hook(stop);
  const CancelHook cancel = [&lane, stopped] {
    if (stopped && stopped()) return true;
    std::lock_guard lock(lane.mutex);
    return !lane.queue.empty() && !lane.queue.front().is_hold;
  };
  InkOffload offload = ink_offload(state_.stroke_pool);
  offload.shape_first = true; // Q is waited for once the shape is out
  try {
    lane.prepared = PreparedHold{partial.id, partial.samples.size(), partial.samples.back().time_us,
                                 h.epoch(), try_hold(h, partial, cancel, offload)};
  } catch (...) {
    lane.prepared.reset(); // cancelled or refused: the hold (if any) recognizes anew
  }
}

void LiveGrouping::snap_hold(Lane& lane, const std::string& device_id, const Pending& pending,
                             std::optional<PreparedHold> prepared) {
  const auto started = std::chrono::steady_clock::now();
  HoldState& hold = *pending.hold;
  GroupHistory& h = lane.history;
  h.ensure(*state_.analyzer, settings_for(state_, pending.stroke.tablet), state_.grouping.get());
  const Stroke& partial = pending.stroke;
  const bool ready = prepared && prepared->stroke_id == partial.id &&
                     prepared->samples == partial.samples.size() && !partial.samples.empty() &&
                     prepared->last_time_us == partial.samples.back().time_us &&
                     prepared->epoch == h.epoch() && h.session() != nullptr;
  const StopCondition stop(started + std::chrono::seconds(state_.limits.max_call_seconds), {});
  std::optional<v1::LiveEvent> event;
  try {
    InkOffload offload = ink_offload(state_.stroke_pool);
    offload.shape_first = true; // as at pen-up: a shape that read no Q does not wait for it
    event = ready
                ? take_hold(h, std::move(prepared->trial), partial.id, hold, state_.next_shape_id)
                : snap_at_hold(h, partial, hold, state_.next_shape_id, cancel_hook(stop), offload);
  } catch (...) {
    event.reset(); // cancelled or refused: as if the pen had not held
  }
  const bool snapped = event.has_value();
  if (snapped) {
    event->set_device_id(device_id);
    v1::Timings* t = event->mutable_shape()->mutable_timings();
    const auto now = std::chrono::steady_clock::now();
    t->set_queued_us(micros(started - pending.submitted));
    t->set_compute_us(micros(now - started));
    t->set_total_us(micros(now - pending.submitted));
    hold.sequence = state_.hub.publish(std::move(*event));
    h.rename(hold.answer, hold.shape_id, hold.sequence);
  }
  {
    std::lock_guard lock(hold.mutex);
    hold.phase = snapped ? HoldState::Phase::kSnapped : HoldState::Phase::kNothing;
  }
  if (snapped) wait_hold_ink(hold);
}

// The held shape is out (and may already follow the pen): now the ink it did not read, for the
// StrokeFinished at release. Should Q fail, the shape stands (certified on the path).
void LiveGrouping::wait_hold_ink(HoldState& hold) {
  if (!hold.ink_later) return;
  try {
    hold.ink = hold.ink_later();
  } catch (const std::exception& e) {
    hold.ink_error = std::string("ink polygon failed: ") + e.what();
  }
  hold.ink_later = nullptr;
}

// Pen-up after a snapped hold: the final shape is the held one moved by the drag, if any.
void LiveGrouping::release(Lane& lane, const std::string& device_id, const Pending& pending) {
  const auto started = std::chrono::steady_clock::now();
  const HoldState& hold = *pending.hold;
  const Stroke& stroke = pending.stroke;
  v1::LiveEvent finished;
  finished.set_device_id(device_id);
  v1::StrokeFinished* f = finished.mutable_stroke_finished();
  to_proto(stroke, f->mutable_stroke());
  *f->mutable_ink_polygon() = hold.ink; // the ink the shape certifies: drawn up to the hold
  f->set_not_analysed(hold.ink_error);
  state_.hub.publish(std::move(finished));

  const Drag drag = drag_after_hold(stroke, hold);
  v1::LiveEvent event = hold_event(device_id, stroke.id, hold, drag, v1::SHAPE_TRIGGER_RELEASE);
  v1::ShapeRecognized* s = event.mutable_shape();
  std::uint64_t shape_id = hold.shape_id;
  if (drag.dragged) { // a new answer, superseding the hold's
    shape_id = ++state_.next_shape_id;
    s->set_shape_id(shape_id);
    s->add_supersedes_shape_ids(hold.shape_id);
    s->add_supersedes_sequences(hold.sequence);
  }
  const auto now = std::chrono::steady_clock::now();
  s->mutable_timings()->set_queued_us(micros(started - pending.submitted));
  s->mutable_timings()->set_compute_us(micros(now - started));
  s->mutable_timings()->set_total_us(micros(now - pending.submitted));
  const std::uint64_t sequence = state_.hub.publish(std::move(event));
  if (drag.dragged && hold.grouped) lane.history.rename(hold.answer, shape_id, sequence);
  if (published_) {
    published_(device_id, stroke.id, hold.ink, settings_for(state_, stroke.tablet));
  }
}

void LiveGrouping::publish_finished(const std::string& device_id, const Stroke& stroke,
                                    const v1::PolygonSet& ink) {
  v1::LiveEvent finished;
  finished.set_device_id(device_id);
  v1::StrokeFinished* f = finished.mutable_stroke_finished();
  to_proto(stroke, f->mutable_stroke());
  *f->mutable_ink_polygon() = ink; // kept for the deconstruction
  state_.hub.publish(std::move(finished));
}

void LiveGrouping::publish(const std::string& device_id, const Stroke& stroke,
                           GroupedStrokeAnalysis& result, const v1::Timings& timings,
                           GroupHistory& history, bool publish_shape) {
  const GroupAnswer answer = history.take(result, stroke.id); // reads the shape: before the swap
  v1::LiveEvent event;
  event.set_device_id(device_id);
  v1::ShapeRecognized* s = event.mutable_shape();
  s->set_stroke_id(stroke.id);
  s->mutable_shape()->Swap(&result.analysis.shape);
  for (auto& alternative : result.analysis.alternatives) s->add_alternatives()->Swap(&alternative);
  *s->mutable_timings() = timings;
  const std::uint64_t shape_id = ++state_.next_shape_id;
  set_group_fields(answer, result.tidy, shape_id, s);
  for (const std::uint64_t q : answer.supersedes_sequences) s->add_supersedes_sequences(q);
  s->set_trigger(v1::SHAPE_TRIGGER_PEN_UP);
  // snap_trigger = hold: grouped (a later held stroke may complete a shape with it), not snapped.
  const std::uint64_t sequence = publish_shape ? state_.hub.publish(std::move(event)) : 0;
  history.remember(result, shape_id, sequence);
}

void LiveGrouping::forget_device(const std::string& device_id) {
  std::lock_guard lock(mutex_);
  const auto it = lanes_.find(device_id);
  if (it == lanes_.end()) return;
  std::lock_guard lane_lock(it->second->mutex);
  if (!it->second->running) lanes_.erase(it);
}

std::optional<v1::PreviewGroup> LiveGrouping::preview_group(const std::string& device_id,
                                                            const Stroke& partial,
                                                            const CancelHook& cancel) {
  std::shared_ptr<const GroupHistory> snapshot;
  {
    std::lock_guard lock(mutex_);
    const auto it = lanes_.find(device_id);
    if (it == lanes_.end()) return std::nullopt;
    std::lock_guard lane_lock(it->second->mutex);
    snapshot = it->second->snapshot;
  }
  if (!snapshot || !snapshot->session() || snapshot->session()->retained_stroke_count() == 0) {
    return std::nullopt;
  }
  // The stroke so far added to a copy: the strand's own grouping is untouched.
  const std::unique_ptr<StrokeGroupSession> session = snapshot->session()->clone();
  GroupedStrokeAnalysis result;
  try {
    result = session->add(partial, false, cancel);
  } catch (const std::exception&) {
    return std::nullopt; // a stroke so far the grouping refuses (or cancelled): no group preview
  }
  const v1::ShapeKind kind = result.analysis.shape.kind();
  if (!result.grouped || result.strokes.size() < 2 || kind == v1::SHAPE_KIND_NONE ||
      kind == v1::SHAPE_KIND_UNSPECIFIED) {
    return std::nullopt;
  }
  v1::PreviewGroup group;
  group.mutable_shape()->Swap(&result.analysis.shape);
  for (const std::size_t i : result.strokes) {
    group.add_replaced_stroke_ids(snapshot->stroke_id(i, partial.id));
  }
  for (const std::size_t id : result.superseded) {
    group.add_supersedes_shape_ids(snapshot->shape_id(id));
  }
  for (const std::string& t : result.tidy) group.add_tidy(t);
  return group;
}

} // namespace penshape::daemon
