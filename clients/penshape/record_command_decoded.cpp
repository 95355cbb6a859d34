// `penshape record FILE --decoded`: the decoded samples of one tablet, re-encoded with a synthetic
// HID pen descriptor (hid_recording_writer.hpp). For a penshaped that predates raw reports: the
// file replays to the same samples, but it is not the tablet's own bytes.
#include <atomic>
#include <cstdio>
#include <fstream>
#include <future>

#include "command.hpp"
#include "daemon_channel.hpp"
#include "device_events.hpp"
#include "hid_recording_writer.hpp"
#include "penshape/proto/pen_types.hpp"
#include "record_command.hpp"

namespace penshape::cli {
namespace {

struct ReadOutcome {
  bool done = false;         // --samples or --strokes reached
  std::uint64_t dropped = 0; // events the daemon dropped for this client
};

// The stream's samples into the file until it ends or a --samples / --strokes limit is reached.
template <typename Reader>
ReadOutcome write_samples(Reader& reader, HidRecordingWriter& writer,
                          const RecordOptions& options) {
  ReadOutcome out;
  std::uint64_t strokes = 0;
  v1::LiveEvent event;
  while (!out.done && reader.Read(&event)) {
    if (event.has_samples()) {
      for (const auto& s : event.samples().samples()) {
        writer.write(proto::from_proto(s));
        if (options.max_samples && writer.reports() >= *options.max_samples) {
          out.done = true;
          break;
        }
      }
    } else if (event.has_stroke_finished()) {
      if (options.max_strokes && ++strokes >= *options.max_strokes) out.done = true;
    } else if (event.has_dropped()) {
      out.dropped += event.dropped().count();
    }
  }
  return out;
}

} // namespace

int record_decoded(v1::Live::Stub& stub, const RecordOptions& options, CancelOnSignal& cancel) {
  int exit_code = kExitOk;
  const std::optional<v1::DeviceInfo> device = choose_device(stub, options, &exit_code);
  if (!device) return exit_code;

  std::ofstream out(options.path, std::ios::trunc);
  if (!out) return record_fail("cannot write " + options.path, kExitBadInput);
  const TabletInfo tablet = proto::from_proto(device->tablet());
  HidRecordingWriter writer(
      out, tablet, "penshaped:" + device->id(),
      "recorded by penshape from device " + device->id() + " (" + device->source() + ")");

  grpc::ClientContext context;
  if (options.duration_seconds) {
    context.set_deadline(
        std::chrono::system_clock::now() +
        std::chrono::microseconds(static_cast<std::int64_t>(*options.duration_seconds * 1e6)));
  }
  v1::SubscribeRequest request;
  request.add_device_ids(device->id());
  request.set_include_samples(true);
  auto reader = stub.Subscribe(&context, request);
  const auto armed = cancel.arm(&context);
  // Subscribe carries no detach events here: a second stream watches for the tablet going away.
  std::atomic<bool> detached{false};
  const std::string device_id = device->id();
  // Ready once the device stream has listed our tablet: a detach after that is seen.
  std::promise<void> listed;
  bool listed_once = false;
  DeviceEvents device_events(stub, [&](const v1::LiveEvent& e) {
    if (e.has_device_attached() && e.device_attached().device().id() == device_id && !listed_once) {
      listed_once = true;
      listed.set_value();
    }
    if (e.has_device_detached() && e.device_detached().device_id() == device_id) {
      detached = true;
      context.TryCancel();
    }
  });
  listed.get_future().wait_for(std::chrono::seconds(10));
  reader->WaitForInitialMetadata();
  std::fprintf(stderr, "penshape record: recording %s into %s (decoded samples; Ctrl-C to stop)\n",
               device_id.c_str(), options.path.c_str());
  const ReadOutcome read = write_samples(*reader, writer, options);
  const bool done = read.done;
  const std::uint64_t dropped = read.dropped;
  if (done) context.TryCancel();
  const grpc::Status status = reader->Finish();
  out.flush();
  if (!out) return record_fail("error while writing " + options.path, kExitInternal);
  std::fprintf(stderr, "penshape record: %zu samples written to %s%s\n", writer.reports(),
               options.path.c_str(), detached ? " (the tablet was unplugged)" : "");
  if (dropped != 0) {
    std::fprintf(stderr,
                 "penshape record: warning: the daemon dropped %llu events for this client "
                 "(it read too slowly); the recording has gaps\n",
                 static_cast<unsigned long long>(dropped));
  }
  const bool normal_end =
      done || detached || cancel.fired() || status.ok() ||
      (options.duration_seconds && status.error_code() == grpc::StatusCode::DEADLINE_EXCEEDED);
  if (normal_end) return kExitOk;
  const RpcFailure f = describe_rpc_failure(status, "Subscribe", options.address);
  return record_fail(f.message, f.exit_code);
}

} // namespace penshape::cli
