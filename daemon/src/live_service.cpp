#include "live_service.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "app_grouping.hpp"
#include "call_runner.hpp"
#include "geometry_service.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "pipeline.hpp"
#include "sample_stream.hpp"
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
  grpc::Status status = analyze_stroke(state_, context, stroke, settings, &analysis, &timings);
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
  grpc::Status status =
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
  return SampleStream(state_, context, stream).run();
}

} // namespace penshape::daemon
