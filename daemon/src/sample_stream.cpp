// One StreamSamples call (sample_stream.hpp).
#include "sample_stream.hpp"

#include <utility>
#include <vector>

#include "app_grouping.hpp"
#include "call_runner.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "pipeline.hpp"

namespace penshape::daemon {

grpc::Status SampleStream::run() {
  v1::StreamSamplesRequest message;
  if (!stream_->Read(&message)) return grpc::Status::OK;
  if (grpc::Status s = start(message); !s.ok()) return s;
  std::size_t batch_index = 0;
  while (stream_->Read(&message)) {
    if (grpc::Status s = add_batch(message, ++batch_index); !s.ok()) return s;
    if (!maybe_preview()) return grpc::Status::CANCELLED;
  }
  if (current_) return finish_stroke(); // the client finished sending: a stroke down ends here
  return grpc::Status::OK;
}

grpc::Status SampleStream::start(const v1::StreamSamplesRequest& first) {
  if (first.kind_case() != v1::StreamSamplesRequest::kStart) {
    return {grpc::StatusCode::INVALID_ARGUMENT, "start: the first message must be a StreamStart"};
  }
  try {
    tablet_ = tablet_from_proto(first.start().tablet(), "start.tablet", true);
    settings_ = apply(settings_for(state_, tablet_),
                      settings_update_from_proto(first.start().settings(), "start.settings"));
  } catch (...) {
    return status_from_current_exception(nullptr);
  }
  hold_.emplace(settings_, state_.analyzer != nullptr); // hold to snap (StreamStart settings)
  previews_ = first.start().include_previews() && state_.analyzer;
  return grpc::Status::OK;
}

grpc::Status SampleStream::add_batch(const v1::StreamSamplesRequest& message,
                                     std::size_t batch_index) {
  const std::string field = "samples (message " + std::to_string(batch_index) + ")";
  if (message.kind_case() != v1::StreamSamplesRequest::kSamples) {
    return {grpc::StatusCode::INVALID_ARGUMENT, field + ": only the first message is a start"};
  }
  for (int i = 0; i < message.samples().samples_size(); ++i) {
    const std::string at = field + ".samples[" + std::to_string(i) + "]";
    if (grpc::Status s = add_sample(sample_from_proto(message.samples().samples(i)), at); !s.ok()) {
      return s;
    }
  }
  return grpc::Status::OK;
}

grpc::Status SampleStream::add_sample(const PenSample& sample, const std::string& at) {
  if (sample.time_us < last_time_) {
    return {grpc::StatusCode::INVALID_ARGUMENT, at + ".time_us goes back in time"};
  }
  last_time_ = sample.time_us;
  if (sample.tip && !current_ && !begin_stroke()) return grpc::Status::CANCELLED;
  if (!current_) return grpc::Status::OK; // hovering
  if (current_->samples.size() >= state_.limits.max_stroke_samples) {
    return {grpc::StatusCode::INVALID_ARGUMENT,
            at + ": the stroke exceeds the limit max_stroke_samples = " +
                std::to_string(state_.limits.max_stroke_samples)};
  }
  current_->samples.push_back(sample);
  if (sample.tip && state_.analyzer &&
      grouping_.ensure(*state_.analyzer, settings_, state_.grouping.get())) {
    std::optional<v1::LiveEvent> held =
        hold_->on_sample(*current_, grouping_, state_.next_shape_id,
                         [context = context_] { return context->IsCancelled(); });
    if (held && !write(std::move(*held))) return grpc::Status::CANCELLED;
  }
  if (!sample.tip) return finish_stroke();
  return grpc::Status::OK;
}

bool SampleStream::begin_stroke() {
  current_.emplace();
  current_->id = state_.next_stroke_id.fetch_add(1);
  current_->tablet = tablet_;
  hold_->start(tablet_);
  v1::LiveEvent started;
  started.mutable_stroke_started()->set_stroke_id(current_->id);
  to_proto(tablet_, started.mutable_stroke_started()->mutable_tablet());
  return write(std::move(started));
}

grpc::Status SampleStream::finish_stroke() {
  Stroke stroke = std::move(*current_);
  current_.reset();
  // A stroke that snapped at a hold: its final shape stands for the analysis.
  std::vector<v1::LiveEvent> released = hold_->release(stroke, grouping_, state_.next_shape_id);
  for (auto& e : released) {
    if (!write(std::move(e))) return grpc::Status::CANCELLED;
  }
  if (!released.empty()) return grpc::Status::OK;
  GroupedStrokeAnalysis result;
  v1::Timings timings;
  v1::LiveEvent finished;
  v1::StrokeFinished* f = finished.mutable_stroke_finished();
  if (state_.analyzer) {
    if (grpc::Status s =
            analyze_grouped(state_, context_, grouping_, stroke, settings_, &result, &timings);
        !s.ok()) {
      return s;
    }
    *f->mutable_ink_polygon() = result.analysis.ink_polygon;
  } else {
    f->set_not_analysed("this build has no stroke analyzer (ink polygon and recognizer)");
  }
  to_proto(stroke, f->mutable_stroke());
  if (!write(std::move(finished))) return grpc::Status::CANCELLED;
  if (!state_.analyzer || result.analysis.shape.kind() == v1::SHAPE_KIND_UNSPECIFIED) {
    return grpc::Status::OK;
  }
  return write_shape(result, timings, stroke.id) ? grpc::Status::OK : grpc::Status::CANCELLED;
}

// The stroke's pen-up answer, remembered by the stream's grouping; written unless snap_trigger =
// hold (then grouped, so a later held stroke may complete a shape with it, but not snapped).
bool SampleStream::write_shape(GroupedStrokeAnalysis& result, const v1::Timings& timings,
                               std::uint64_t stroke_id) {
  v1::LiveEvent shape;
  v1::ShapeRecognized* r = shape.mutable_shape();
  const GroupAnswer answer = grouping_.take(result, stroke_id); // reads the shape: first
  r->set_stroke_id(stroke_id);
  *r->mutable_shape() = std::move(result.analysis.shape);
  for (auto& alternative : result.analysis.alternatives) *r->add_alternatives() = alternative;
  *r->mutable_timings() = timings;
  const std::uint64_t shape_id = ++state_.next_shape_id;
  set_group_fields(answer, result.tidy, shape_id, r);
  for (std::size_t i = 0; i < answer.supersedes_shape_ids.size(); ++i) {
    r->add_supersedes_sequences(0); // the stream's events are not published
  }
  r->set_trigger(v1::SHAPE_TRIGGER_PEN_UP);
  grouping_.remember(result, shape_id, 0);
  return hold_->hold_only() || write(std::move(shape));
}

// The stroke in progress after a batch, at the pipeline's pace; a failed preview is skipped (a
// hint: the stroke still gets its shape).
bool SampleStream::maybe_preview() {
  const auto now = std::chrono::steady_clock::now();
  if (!previews_ || !current_ || now - last_preview_ < Pipeline::kPreviewInterval) return true;
  last_preview_ = now;
  std::vector<v1::Shape> candidates;
  try {
    candidates = state_.analyzer->preview(*current_, settings_,
                                          [context = context_] { return context->IsCancelled(); });
  } catch (...) {
    return true;
  }
  if (candidates.empty()) return true;
  v1::LiveEvent event;
  v1::PreviewCandidates* preview = event.mutable_preview();
  preview->set_stroke_id(current_->id);
  for (auto& c : candidates) *preview->add_candidates() = std::move(c);
  return write(std::move(event));
}

bool SampleStream::write(v1::LiveEvent event) {
  event.set_published_us(monotonic_us());
  event.set_device_id("stream");
  return stream_->Write(event);
}

} // namespace penshape::daemon
