#include "live_service.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "app_grouping.hpp"
#include "call_runner.hpp"
#include "geometry_service.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "pipeline.hpp"
#include "stream_hold.hpp"
#include "thread_scheduling.hpp"

namespace penshape::daemon {
namespace {

// How often an idle stream looks at its call's cancellation. Events and shutdown wake it at once
// (condition variable); this only bounds how long a vanished client keeps its subscriber slot, at
// two wake-ups a second per idle subscriber.
constexpr std::chrono::milliseconds kCancelPoll{500};

// Forwards a subscription's events until the client goes away (CANCELLED) or the hub closes and
// the queue is drained (OK: the daemon stopped after delivering everything).
template <typename Writer>
grpc::Status pump(Subscription& subscription, grpc::ServerContext* context, Writer* writer) {
  request_short_slice_once(); // this thread writes the stream: waking it must not wait a slice
  for (;;) {
    if (context->IsCancelled()) return grpc::Status::CANCELLED;
    Subscription::Delivery delivery = subscription.next(kCancelPoll);
    if (!delivery.event) {
      if (subscription.finished()) return grpc::Status::OK;
      continue;
    }
    // While a backlog drains, writes are coalesced (buffer hint): fewer syscalls let a lagging
    // subscriber catch up; the last queued event goes out at once.
    grpc::WriteOptions coalesce;
    coalesce.set_buffer_hint();
    if (delivery.dropped != 0) {
      v1::LiveEvent notice;
      notice.set_published_us(monotonic_us());
      notice.mutable_dropped()->set_count(delivery.dropped);
      notice.mutable_dropped()->set_total(delivery.dropped_total);
      if (!writer->Write(notice, coalesce)) return grpc::Status::CANCELLED;
    }
    if (!writer->Write(*delivery.event, delivery.more ? coalesce : grpc::WriteOptions())) {
      return grpc::Status::CANCELLED;
    }
  }
}

std::size_t queue_capacity(std::uint32_t requested, const Limits& limits) {
  if (requested == 0) return limits.subscriber_queue_events;
  return std::min<std::size_t>(requested, limits.subscriber_queue_events);
}

} // namespace

grpc::Status LiveServiceImpl::subscribe(EventFilter filter, std::size_t capacity,
                                        std::unique_ptr<Subscription>* out) {
  ShapeHub::Refusal why = ShapeHub::Refusal::kNone;
  *out = state_.hub.subscribe(std::move(filter), capacity, &why);
  if (*out) return grpc::Status::OK;
  if (why == ShapeHub::Refusal::kClosed) {
    return {grpc::StatusCode::UNAVAILABLE, "the daemon is shutting down"};
  }
  if (why == ShapeHub::Refusal::kRawFull) {
    return {grpc::StatusCode::RESOURCE_EXHAUSTED,
            "include_raw_reports: too many subscribers take raw reports (limit "
            "max_raw_report_subscribers = " +
                std::to_string(state_.limits.max_raw_report_subscribers) + ")"};
  }
  return {grpc::StatusCode::RESOURCE_EXHAUSTED, "too many subscribers (limit max_subscribers = " +
                                                    std::to_string(state_.limits.max_subscribers) +
                                                    ")"};
}

grpc::Status LiveServiceImpl::ListDevices(grpc::ServerContext* /*context*/,
                                          const v1::ListDevicesRequest* /*request*/,
                                          v1::ListDevicesResponse* response) {
  for (const DeviceDescriptor& device : state_.devices.list()) {
    to_proto(device, response->add_devices());
  }
  return grpc::Status::OK;
}

grpc::Status LiveServiceImpl::WatchDevices(grpc::ServerContext* context,
                                           const v1::WatchDevicesRequest* /*request*/,
                                           grpc::ServerWriter<v1::LiveEvent>* writer) {
  EventFilter filter;
  filter.devices = true;
  filter.strokes = false;
  std::unique_ptr<Subscription> subscription;
  // Subscribe before listing so no attach is missed (one may then appear twice).
  if (grpc::Status s = subscribe(filter, state_.limits.subscriber_queue_events, &subscription);
      !s.ok()) {
    return s;
  }
  for (const DeviceDescriptor& device : state_.devices.list()) {
    v1::LiveEvent event;
    event.set_published_us(monotonic_us());
    event.set_device_id(device.id);
    to_proto(device, event.mutable_device_attached()->mutable_device());
    if (!writer->Write(event)) return grpc::Status::CANCELLED;
  }
  return pump(*subscription, context, writer);
}

grpc::Status LiveServiceImpl::Subscribe(grpc::ServerContext* context,
                                        const v1::SubscribeRequest* request,
                                        grpc::ServerWriter<v1::LiveEvent>* writer) {
  EventFilter filter;
  filter.samples = request->include_samples();
  filter.previews = request->include_previews();
  filter.deconstructions = request->include_deconstruction();
  filter.raw_reports = request->include_raw_reports();
  filter.device_ids.insert(request->device_ids().begin(), request->device_ids().end());
  std::unique_ptr<Subscription> subscription;
  if (grpc::Status s = subscribe(
          filter, queue_capacity(request->max_queued_events(), state_.limits), &subscription);
      !s.ok()) {
    return s;
  }
  // Headers now, so the client knows it is subscribed before the first event.
  writer->SendInitialMetadata();
  return pump(*subscription, context, writer);
}

grpc::Status LiveServiceImpl::SubmitStroke(grpc::ServerContext* context,
                                           const v1::SubmitStrokeRequest* request,
                                           v1::SubmitStrokeResponse* response) {
  if (request->group_key().size() > state_.limits.max_group_key_bytes) {
    return {grpc::StatusCode::INVALID_ARGUMENT,
            "group_key: " + std::to_string(request->group_key().size()) +
                " bytes, more than the limit max_group_key_bytes = " +
                std::to_string(state_.limits.max_group_key_bytes)};
  }
  Stroke stroke;
  PenSettings settings;
  try {
    stroke = stroke_from_proto(request->stroke(), "stroke", state_.limits, true);
    settings = apply(settings_for(state_, stroke.tablet),
                     settings_update_from_proto(request->settings(), "settings"));
  } catch (...) {
    return status_from_current_exception(nullptr);
  }
  stroke.id = state_.next_stroke_id.fetch_add(1);
  if (!request->group_key().empty()) {
    return submit_grouped(context, *request, stroke, settings, response);
  }
  StrokeAnalysis analysis;
  v1::Timings timings;
  const grpc::Status status =
      analyze_stroke(state_, context, stroke, settings, &analysis, &timings);
  if (!status.ok()) return status;
  if (request->publish()) publish_stroke(state_.hub, "app", stroke, &analysis, "", timings);
  response->set_stroke_id(stroke.id);
  const v1::ShapeKind kind = analysis.shape.kind();
  if (kind != v1::SHAPE_KIND_NONE && kind != v1::SHAPE_KIND_UNSPECIFIED) {
    response->add_replaced_stroke_ids(stroke.id); // a stroke alone replaces its own ink
  }
  *response->mutable_ink_polygon() = std::move(analysis.ink_polygon);
  *response->mutable_shape() = std::move(analysis.shape);
  for (auto& alternative : analysis.alternatives) *response->add_alternatives() = alternative;
  *response->mutable_timings() = timings;
  return grpc::Status::OK;
}

grpc::Status LiveServiceImpl::submit_grouped(grpc::ServerContext* context,
                                             const v1::SubmitStrokeRequest& request,
                                             const Stroke& stroke, const PenSettings& settings,
                                             v1::SubmitStrokeResponse* response) {
  const std::shared_ptr<GroupKeys::Group> group = state_.group_keys.get(request.group_key());
  // One stroke of a key at a time, in the order the calls take the lock.
  std::lock_guard lock(group->mutex);
  GroupedStrokeAnalysis result;
  v1::Timings timings;
  const grpc::Status status =
      analyze_grouped(state_, context, group->history, stroke, settings, &result, &timings);
  if (!status.ok()) return status;
  const GroupAnswer answer = group->history.take(result, stroke.id);
  const std::uint64_t shape_id = ++state_.next_shape_id;
  std::uint64_t sequence = 0;
  if (request.publish()) {
    sequence = publish_stroke(state_.hub, "app", stroke, &result.analysis, "", timings,
                              [&](v1::ShapeRecognized& s) {
                                set_group_fields(answer, result.tidy, shape_id, &s);
                                for (const std::uint64_t q : answer.supersedes_sequences) {
                                  s.add_supersedes_sequences(q);
                                }
                              });
  }
  group->history.remember(result, shape_id, sequence);
  response->set_stroke_id(stroke.id);
  *response->mutable_ink_polygon() = std::move(result.analysis.ink_polygon);
  *response->mutable_shape() = std::move(result.analysis.shape);
  for (auto& alternative : result.analysis.alternatives) {
    response->add_alternatives()->Swap(&alternative);
  }
  *response->mutable_timings() = timings;
  set_group_fields(answer, result.tidy, shape_id, response);
  return grpc::Status::OK;
}

grpc::Status LiveServiceImpl::StreamSamples(
    grpc::ServerContext* context,
    grpc::ServerReaderWriter<v1::LiveEvent, v1::StreamSamplesRequest>* stream) {
  // A slot among the subscribers (the limit counts every live stream); it receives nothing.
  EventFilter nothing;
  nothing.strokes = false;
  std::unique_ptr<Subscription> slot;
  if (grpc::Status s = subscribe(nothing, 1, &slot); !s.ok()) return s;

  v1::StreamSamplesRequest message;
  if (!stream->Read(&message)) return grpc::Status::OK;
  if (message.kind_case() != v1::StreamSamplesRequest::kStart) {
    return {grpc::StatusCode::INVALID_ARGUMENT, "start: the first message must be a StreamStart"};
  }
  TabletInfo tablet;
  PenSettings settings;
  try {
    tablet = tablet_from_proto(message.start().tablet(), "start.tablet", true);
    settings = apply(settings_for(state_, tablet),
                     settings_update_from_proto(message.start().settings(), "start.settings"));
  } catch (...) {
    return status_from_current_exception(nullptr);
  }

  // Strokes run from tip down to tip up (stroke.hpp), the segmenter's rule for one pen.
  std::optional<Stroke> current;
  std::int64_t last_time = INT64_MIN;
  auto write_event = [&](v1::LiveEvent event) {
    event.set_published_us(monotonic_us());
    event.set_device_id("stream");
    return stream->Write(event);
  };
  // The stream's own grouping: its strokes group with each other only.
  GroupHistory grouping;
  StreamHold hold(settings, state_.analyzer != nullptr); // hold to snap (StreamStart settings)
  auto finish_stroke = [&]() -> grpc::Status {
    Stroke stroke = std::move(*current);
    current.reset();
    // A stroke that snapped at a hold: its final shape stands for the analysis.
    std::vector<v1::LiveEvent> released = hold.release(stroke, grouping, state_.next_shape_id);
    for (auto& e : released) {
      if (!write_event(std::move(e))) return grpc::Status::CANCELLED;
    }
    if (!released.empty()) return grpc::Status::OK;
    GroupedStrokeAnalysis result;
    StrokeAnalysis& analysis = result.analysis;
    v1::Timings timings;
    std::string not_analysed;
    if (state_.analyzer) {
      const grpc::Status s =
          analyze_grouped(state_, context, grouping, stroke, settings, &result, &timings);
      if (!s.ok()) return s;
    } else {
      not_analysed = "this build has no stroke analyzer (ink polygon and recognizer)";
    }
    v1::LiveEvent finished;
    v1::StrokeFinished* f = finished.mutable_stroke_finished();
    to_proto(stroke, f->mutable_stroke());
    f->set_not_analysed(not_analysed);
    if (state_.analyzer) *f->mutable_ink_polygon() = analysis.ink_polygon;
    if (!write_event(std::move(finished))) return grpc::Status::CANCELLED;
    if (state_.analyzer && analysis.shape.kind() != v1::SHAPE_KIND_UNSPECIFIED) {
      v1::LiveEvent shape;
      v1::ShapeRecognized* r = shape.mutable_shape();
      const GroupAnswer answer = grouping.take(result, stroke.id); // reads the shape: first
      r->set_stroke_id(stroke.id);
      *r->mutable_shape() = std::move(analysis.shape);
      for (auto& alternative : analysis.alternatives) *r->add_alternatives() = alternative;
      *r->mutable_timings() = timings;
      const std::uint64_t shape_id = ++state_.next_shape_id;
      set_group_fields(answer, result.tidy, shape_id, r);
      for (std::size_t i = 0; i < answer.supersedes_shape_ids.size(); ++i) {
        r->add_supersedes_sequences(0); // the stream's events are not published
      }
      r->set_trigger(v1::SHAPE_TRIGGER_PEN_UP);
      grouping.remember(result, shape_id, 0);
      // snap_trigger = hold: grouped (a later held stroke may complete a shape), not snapped.
      if (!hold.hold_only() && !write_event(std::move(shape))) return grpc::Status::CANCELLED;
    }
    return grpc::Status::OK;
  };

  // Previews: the stroke in progress after a batch, at the pipeline's pace.
  const bool previews = message.start().include_previews() && state_.analyzer;
  auto last_preview = std::chrono::steady_clock::time_point{};
  auto maybe_preview = [&]() -> bool {
    const auto now = std::chrono::steady_clock::now();
    if (!previews || !current || now - last_preview < Pipeline::kPreviewInterval) return true;
    last_preview = now;
    std::vector<v1::Shape> candidates;
    try {
      candidates = state_.analyzer->preview(*current, settings,
                                            [context] { return context->IsCancelled(); });
    } catch (...) {
      return true; // a hint: a failed preview is skipped, the stroke still gets its shape
    }
    if (candidates.empty()) return true;
    v1::LiveEvent event;
    v1::PreviewCandidates* preview = event.mutable_preview();
    preview->set_stroke_id(current->id);
    for (auto& c : candidates) *preview->add_candidates() = std::move(c);
    return write_event(std::move(event));
  };

  std::size_t batch_index = 0;
  while (stream->Read(&message)) {
    ++batch_index;
    const std::string field = "samples (message " + std::to_string(batch_index) + ")";
    if (message.kind_case() != v1::StreamSamplesRequest::kSamples) {
      return {grpc::StatusCode::INVALID_ARGUMENT, field + ": only the first message is a start"};
    }
    for (int i = 0; i < message.samples().samples_size(); ++i) {
      const PenSample sample = sample_from_proto(message.samples().samples(i));
      const std::string at = field + ".samples[" + std::to_string(i) + "]";
      if (sample.time_us < last_time) {
        return {grpc::StatusCode::INVALID_ARGUMENT, at + ".time_us goes back in time"};
      }
      last_time = sample.time_us;
      if (sample.tip && !current) {
        current.emplace();
        current->id = state_.next_stroke_id.fetch_add(1);
        current->tablet = tablet;
        hold.start(tablet);
        v1::LiveEvent started;
        started.mutable_stroke_started()->set_stroke_id(current->id);
        to_proto(tablet, started.mutable_stroke_started()->mutable_tablet());
        if (!write_event(std::move(started))) return grpc::Status::CANCELLED;
      }
      if (!current) continue;
      if (current->samples.size() >= state_.limits.max_stroke_samples) {
        return {grpc::StatusCode::INVALID_ARGUMENT,
                at + ": the stroke exceeds the limit max_stroke_samples = " +
                    std::to_string(state_.limits.max_stroke_samples)};
      }
      current->samples.push_back(sample);
      if (sample.tip && state_.analyzer &&
          grouping.ensure(*state_.analyzer, settings, state_.grouping.get())) {
        std::optional<v1::LiveEvent> held = hold.on_sample(
            *current, grouping, state_.next_shape_id, [context] { return context->IsCancelled(); });
        if (held && !write_event(std::move(*held))) return grpc::Status::CANCELLED;
      }
      if (!sample.tip) {
        if (grpc::Status s = finish_stroke(); !s.ok()) return s;
      }
    }
    if (!maybe_preview()) return grpc::Status::CANCELLED;
  }
  // The client finished sending: a stroke still down ends here.
  if (current) return finish_stroke();
  return grpc::Status::OK;
}

} // namespace penshape::daemon
