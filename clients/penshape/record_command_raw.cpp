// `penshape record FILE`: the tablet's own descriptor and every raw report it sends, as penshaped
// forwards them (SubscribeRequest.include_raw_reports), written as a hid-recorder capture.
//
// One ordered stream carries everything: with raw reports, Subscribe also delivers the chosen
// devices' attach and detach events, so the capture starts with the device's first report after
// the subscription (or after its attach, with --wait) and ends with its last one before the
// detach, and no second stream can race the first.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "command.hpp"
#include "daemon_channel.hpp"
#include "record_command.hpp"
#include "record_command_capture.hpp"

namespace penshape::cli {
namespace {

std::string too_old_message(const v1::DeviceInfo& device, const std::string& address) {
  return "penshaped at " + address + " gives no HID report descriptor for '" + device.id() +
         "': it predates raw reports (or the device has none), so its own bytes cannot be "
         "captured; update penshaped, or record its decoded samples with --decoded";
}

// The devices that --device (if given) accepts.
bool wanted(const RecordOptions& options, const std::string& id) {
  return !options.device || *options.device == id;
}

class RawRecording {
 public:
  RawRecording(const RecordOptions& options, std::ofstream& out) : options_(options), out_(out) {}

  // Starts capturing `device`: writes the header. False (after printing why) when the device
  // cannot be captured.
  bool start(const v1::DeviceInfo& device) {
    std::optional<drivers::Recording> header;
    try {
      header = capture_header(device);
    } catch (const std::invalid_argument& e) {
      error_ = record_fail(e.what(), kExitInternal);
      return false;
    }
    if (!header) {
      error_ = record_fail(too_old_message(device, options_.address), kExitInternal);
      return false;
    }
    device_id_ = device.id();
    writer_ = std::make_unique<CaptureWriter>(
        out_, *header,
        "recorded by `penshape record` from penshaped device " + device.id() + " (" +
            device.source() + "): the device's own report descriptor and reports",
        options_.max_strokes.has_value());
    std::fprintf(stderr, "penshape record: recording %s into %s (Ctrl-C to stop)\n",
                 device_id_.c_str(), options_.path.c_str());
    return true;
  }

  // Handles one event of the stream; false when the recording is complete.
  bool on_event(const v1::LiveEvent& event) {
    if (event.has_dropped()) {
      dropped_ += event.dropped().count();
      return true;
    }
    if (!writer_) {
      if (event.has_device_attached() && wanted(options_, event.device_id())) {
        return start(event.device_attached().device());
      }
      return true; // reports of other devices, or before ours attached
    }
    if (event.device_id() != device_id_) return true;
    if (event.has_raw_report()) {
      writer_->write(event.raw_report().data(), event.raw_report().time_us());
    } else if (event.has_device_detached()) {
      detached_ = true;
      return false;
    } else if (event.has_stroke_finished() && options_.max_strokes) {
      const auto& samples = event.stroke_finished().stroke().samples();
      if (samples.empty()) return true;
      // The stroke's last sample carries the time of the report that ended it.
      const std::int64_t end_us = samples.rbegin()->time_us();
      if (++strokes_ >= *options_.max_strokes) {
        cut_ = writer_->cut_through(end_us);
        return false;
      }
      writer_->forget_before(end_us);
    }
    return true;
  }

  [[nodiscard]] bool started() const { return writer_ != nullptr; }
  [[nodiscard]] int error() const { return error_; }
  [[nodiscard]] bool detached() const { return detached_; }
  [[nodiscard]] std::uint64_t dropped() const { return dropped_; }
  [[nodiscard]] const std::optional<CaptureWriter::Cut>& cut() const { return cut_; }
  [[nodiscard]] std::size_t reports() const {
    return cut_ ? cut_->reports : (writer_ ? writer_->reports() : 0);
  }

 private:
  const RecordOptions& options_;
  std::ofstream& out_;
  std::unique_ptr<CaptureWriter> writer_;
  std::string device_id_;
  int error_ = kExitOk;
  bool detached_ = false;
  std::uint64_t dropped_ = 0;
  std::uint64_t strokes_ = 0;
  std::optional<CaptureWriter::Cut> cut_;
};

// --wait: a tablet attached already (after the subscription its reports are all queued) starts
// the recording, or the first one the stream announces will. kExitOk, or why not.
int start_attached(v1::Live::Stub& stub, const RecordOptions& options, RawRecording& recording) {
  int failed = kExitOk;
  const std::optional<v1::ListDevicesResponse> devices = list_devices(stub, options, &failed);
  if (!devices) return failed;
  std::vector<const v1::DeviceInfo*> present;
  for (const auto& d : devices->devices()) {
    if (wanted(options, d.id())) present.push_back(&d);
  }
  if (present.size() > 1) {
    return record_fail("several tablets are attached: choose one with --device ID", kExitInternal);
  }
  if (present.size() == 1) return recording.start(*present.front()) ? kExitOk : recording.error();
  const std::string what = options.device ? "'" + *options.device + "'" : "a tablet";
  std::fprintf(stderr, "penshape record: waiting for %s to be attached (Ctrl-C to stop)\n",
               what.c_str());
  return kExitOk;
}

// The subscription's raw reports for the recording (one device, or any with --wait).
v1::SubscribeRequest raw_request(const RecordOptions& options,
                                 const std::optional<v1::DeviceInfo>& device) {
  v1::SubscribeRequest request;
  if (device) {
    request.add_device_ids(device->id());
  } else if (options.device) {
    request.add_device_ids(*options.device);
  }
  request.set_include_raw_reports(true);
  return request;
}

// After the stream ended: the file complete (trimmed to the last stroke with --strokes), or why
// not; `remove` is told whether the file must go (nothing captured).
int close_recording(const RecordOptions& options, RawRecording& recording, std::ofstream& out,
                    bool normal_end, const grpc::Status& status, bool& remove) {
  out.flush();
  const bool written = static_cast<bool>(out);
  out.close();
  if (!written) return record_fail("error while writing " + options.path, kExitInternal);
  if (recording.cut()) {
    std::error_code ec;
    std::filesystem::resize_file(options.path, recording.cut()->bytes, ec);
    if (ec) return record_fail("cannot trim " + options.path + ": " + ec.message(), kExitInternal);
  }
  if (!normal_end) {
    const RpcFailure f = describe_rpc_failure(status, "Subscribe", options.address);
    // A call refused or broken before any report (e.g. the raw-subscriber limit): no half file.
    remove = recording.reports() == 0;
    return record_fail(f.message, f.exit_code);
  }
  if (!recording.started()) {
    remove = true;
    return record_fail("no tablet was attached; nothing recorded", kExitInternal);
  }
  std::fprintf(stderr, "penshape record: %zu reports written to %s%s\n", recording.reports(),
               options.path.c_str(), recording.detached() ? " (the tablet was unplugged)" : "");
  if (recording.dropped() != 0) {
    return record_fail("the daemon dropped " + std::to_string(recording.dropped()) +
                           " events for this client (it read too slowly): " + options.path +
                           " has gaps and does not replay like the tablet",
                       kExitInternal);
  }
  return kExitOk;
}

} // namespace

int record_raw(v1::Live::Stub& stub, const RecordOptions& options, CancelOnSignal& cancel) {
  int exit_code = kExitOk;
  std::optional<v1::DeviceInfo> device;
  if (!options.wait) {
    device = choose_device(stub, options, &exit_code);
    if (!device) return exit_code;
    // Refuse before touching FILE.
    if (!device->has_hid() || device->hid().report_descriptor().empty()) {
      return record_fail(too_old_message(*device, options.address), kExitInternal);
    }
  }
  std::ofstream out(options.path, std::ios::trunc | std::ios::binary);
  if (!out) return record_fail("cannot write " + options.path, kExitBadInput);
  RawRecording recording(options, out);
  const auto give_up = [&](int code) {
    out.close();
    std::filesystem::remove(options.path); // nothing captured: no half file
    return code;
  };

  grpc::ClientContext context;
  if (options.duration_seconds) {
    context.set_deadline(
        std::chrono::system_clock::now() +
        std::chrono::microseconds(static_cast<std::int64_t>(*options.duration_seconds * 1e6)));
  }
  auto reader = stub.Subscribe(&context, raw_request(options, device));
  const auto armed = cancel.arm(&context);
  reader->WaitForInitialMetadata(); // subscribed: nothing from now on is missed
  const int started = device ? (recording.start(*device) ? kExitOk : recording.error())
                             : start_attached(stub, options, recording);
  if (started != kExitOk) {
    context.TryCancel();
    (void)reader->Finish();
    return give_up(started);
  }

  v1::LiveEvent event;
  bool done = false;
  while (!done && reader->Read(&event)) {
    done = !recording.on_event(event);
    if (recording.error() != kExitOk) break;
  }
  if (done || recording.error() != kExitOk) context.TryCancel();
  const grpc::Status status = reader->Finish();
  if (recording.error() != kExitOk) return give_up(recording.error());
  const bool normal_end =
      done || cancel.fired() || status.ok() ||
      (options.duration_seconds && status.error_code() == grpc::StatusCode::DEADLINE_EXCEEDED);
  bool remove = false;
  const int code = close_recording(options, recording, out, normal_end, status, remove);
  if (remove) std::filesystem::remove(options.path); // nothing captured: no half file
  return code;
}

} // namespace penshape::cli
