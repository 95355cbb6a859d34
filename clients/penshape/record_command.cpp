// `penshape record FILE`: capture what a tablet draws, through penshaped, as a hid-recorder file
// that `penshape replay` and hid-tools can play back.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <future>
#include <optional>
#include <string>

#include "args.hpp"
#include "cancel_on_signal.hpp"
#include "command.hpp"
#include "daemon_channel.hpp"
#include "device_events.hpp"
#include "hid_recording_writer.hpp"
#include "live_commands.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape record FILE [--device ID] [--strokes N] [--samples N]\n"
    "                       [--duration SECONDS] [--socket PATH | --address ADDR]\n\n"
    "Records the pen samples of one tablet, as penshaped decodes them, into FILE in the\n"
    "hid-recorder text format (R:/N:/P:/I: header, one E: line per sample), until Ctrl-C,\n"
    "--strokes, --samples, --duration, or the tablet is unplugged.\n\n"
    "The daemon's API carries decoded samples, not raw reports: FILE describes the tablet with\n"
    "a synthetic HID pen descriptor (same ranges and resolution) so any HID parser replays the\n"
    "same samples; vendor-specific report bytes are not kept.\n\n"
    "options:\n"
    "  --device ID        the tablet to record (needed when several are attached)\n"
    "  --strokes N        stop after N finished strokes\n"
    "  --samples N        stop after N samples\n"
    "  --duration SECONDS stop after this time\n"
    "%s\n"
    "Exit codes: 0 recorded, 2 bad usage or FILE not writable, 1 daemon not running, no such\n"
    "device, or failed.\n";

std::optional<std::uint64_t> positive_integer(const ParsedArgs& args, std::string_view name) {
  const auto v = args.number(name);
  if (!v) return std::nullopt;
  if (*v < 1 || *v > 1e15 || std::floor(*v) != *v) {
    throw UsageError("option '" + std::string(name) + "' needs a positive integer");
  }
  return static_cast<std::uint64_t>(*v);
}

TabletInfo tablet_from(const v1::TabletInfo& t) {
  TabletInfo out;
  out.bus = static_cast<Bus>(t.bus());
  out.vendor_id = static_cast<std::uint16_t>(t.vendor_id());
  out.product_id = static_cast<std::uint16_t>(t.product_id());
  out.name = t.name();
  out.x_max = t.x_max();
  out.y_max = t.y_max();
  out.pressure_max = t.pressure_max();
  out.x_resolution = t.x_resolution();
  out.y_resolution = t.y_resolution();
  out.has_tilt = t.has_tilt();
  return out;
}

PenSample sample_from(const v1::PenSample& s) {
  PenSample out;
  out.time_us = s.time_us();
  out.x = s.x();
  out.y = s.y();
  out.pressure = s.pressure();
  out.tilt_x = static_cast<std::int16_t>(std::clamp(s.tilt_x(), -32768, 32767));
  out.tilt_y = static_cast<std::int16_t>(std::clamp(s.tilt_y(), -32768, 32767));
  out.buttons = s.buttons();
  out.in_range = s.in_range();
  out.tip = s.tip();
  return out;
}

int fail(const std::string& message, int code) {
  std::fprintf(stderr, "penshape record: %s\n", message.c_str());
  return code;
}

} // namespace

int run_record(std::span<const std::string_view> args) {
  const ParsedArgs parsed(
      args, live_arg_spec(
                {.flags = {}, .options = {"--device", "--strokes", "--samples", "--duration"}}));
  if (parsed.flag("--help")) {
    std::printf(kHelp, kLiveOptionsHelp);
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) {
    throw UsageError(parsed.positionals().empty() ? "missing the output FILE"
                                                  : "expected one output FILE");
  }
  const std::string path = parsed.positionals().front();
  const std::string address = daemon_address(parsed);
  const auto max_strokes = positive_integer(parsed, "--strokes");
  const auto max_samples = positive_integer(parsed, "--samples");
  const auto duration = parsed.number("--duration");
  if (duration && (*duration <= 0 || *duration > 1e7)) {
    throw UsageError("option '--duration' needs a number of seconds > 0");
  }

  CancelOnSignal cancel; // before any gRPC thread exists
  try {
    auto stub = v1::Live::NewStub(connect_to_daemon(address));
    v1::ListDevicesResponse devices;
    {
      grpc::ClientContext context;
      context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
      const grpc::Status status = stub->ListDevices(&context, {}, &devices);
      if (!status.ok()) {
        const RpcFailure f = describe_rpc_failure(status, "ListDevices", address);
        return fail(f.message, f.exit_code);
      }
    }
    const v1::DeviceInfo* device = nullptr;
    const auto wanted = parsed.value("--device");
    for (const auto& d : devices.devices()) {
      if (wanted ? d.id() == *wanted : true) device = &d;
    }
    if (wanted && device == nullptr) {
      return fail("no device '" + *wanted + "' is attached (see `penshape devices`)",
                  kExitInternal);
    }
    if (!wanted && devices.devices_size() != 1) {
      return fail(devices.devices_size() == 0
                      ? "no tablets are attached to penshaped at " + address
                      : "several tablets are attached: choose one with --device ID",
                  kExitInternal);
    }

    std::ofstream out(path, std::ios::trunc);
    if (!out) return fail("cannot write " + path, kExitBadInput);
    const TabletInfo tablet = tablet_from(device->tablet());
    HidRecordingWriter writer(
        out, tablet, "penshaped:" + device->id(),
        "recorded by penshape from device " + device->id() + " (" + device->source() + ")");

    grpc::ClientContext context;
    if (duration) {
      context.set_deadline(std::chrono::system_clock::now() +
                           std::chrono::microseconds(static_cast<std::int64_t>(*duration * 1e6)));
    }
    v1::SubscribeRequest request;
    request.add_device_ids(device->id());
    request.set_include_samples(true);
    auto reader = stub->Subscribe(&context, request);
    cancel.arm(&context);
    // Subscribe carries no detach events: a second stream watches for the tablet going away.
    std::atomic<bool> detached{false};
    const std::string device_id = device->id();
    // Ready once the device stream has listed our tablet: a detach after that is seen.
    std::promise<void> listed;
    bool listed_once = false;
    DeviceEvents device_events(*stub, [&](const v1::LiveEvent& e) {
      if (e.has_device_attached() && e.device_attached().device().id() == device_id &&
          !listed_once) {
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
    std::fprintf(stderr, "penshape record: recording %s into %s (Ctrl-C to stop)\n",
                 device->id().c_str(), path.c_str());
    std::uint64_t strokes = 0;
    bool done = false;
    std::uint64_t dropped = 0;
    v1::LiveEvent event;
    while (!done && reader->Read(&event)) {
      if (event.has_samples()) {
        for (const auto& s : event.samples().samples()) {
          writer.write(sample_from(s));
          if (max_samples && writer.reports() >= *max_samples) {
            done = true;
            break;
          }
        }
      } else if (event.has_stroke_finished()) {
        if (max_strokes && ++strokes >= *max_strokes) done = true;
      } else if (event.has_dropped()) {
        dropped += event.dropped().count();
      }
    }
    if (done) context.TryCancel();
    const grpc::Status status = reader->Finish();
    out.flush();
    if (!out) return fail("error while writing " + path, kExitInternal);
    std::fprintf(stderr, "penshape record: %zu samples written to %s%s\n", writer.reports(),
                 path.c_str(), detached ? " (the tablet was unplugged)" : "");
    if (dropped != 0) {
      std::fprintf(stderr,
                   "penshape record: warning: the daemon dropped %llu events for this client "
                   "(it read too slowly); the recording has gaps\n",
                   static_cast<unsigned long long>(dropped));
    }
    const bool normal_end =
        done || detached || cancel.fired() || status.ok() ||
        (duration && status.error_code() == grpc::StatusCode::DEADLINE_EXCEEDED);
    if (normal_end) return kExitOk;
    const RpcFailure f = describe_rpc_failure(status, "Subscribe", address);
    return fail(f.message, f.exit_code);
  } catch (const DaemonUnavailable& e) {
    return fail(e.what(), kExitInternal);
  }
}

} // namespace penshape::cli
