// `penshape record FILE`: capture one tablet, through penshaped, as a hid-recorder file that
// `penshape replay`, `penshaped --replay` and hid-tools play back like the tablet itself.
#include "record_command.hpp"

#include <cstdio>

#include "args.hpp"
#include "command.hpp"
#include "daemon_channel.hpp"
#include "live_commands.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape record FILE [--device ID] [--duration SECONDS] [--strokes N] [--wait]\n"
    "                       [--decoded [--samples N]] [--socket PATH | --address ADDR]\n\n"
    "Captures one tablet, through penshaped, into FILE in the hid-recorder text format: the\n"
    "tablet's own HID report descriptor (R:), name (N:), physical path (P:), bus and ids (I:),\n"
    "and every input report it sends, byte for byte (E: lines, times relative to the first),\n"
    "until Ctrl-C, --duration, --strokes, or the tablet is unplugged. FILE replays like the\n"
    "tablet: `penshape replay --local FILE`, `penshaped --replay FILE`, hid-tools' hid-replay.\n\n"
    "options:\n"
    "  --device ID        the tablet to record (needed when several are attached)\n"
    "  --wait             wait for a tablet (or --device ID) to be attached instead of failing;\n"
    "                     all its reports from the first one on are captured\n"
    "  --strokes N        stop at the end of the N-th finished stroke (FILE ends with the report\n"
    "                     that ended it)\n"
    "  --duration SECONDS stop after this time\n"
    "  --decoded          for a penshaped older than raw reports: record its decoded samples\n"
    "                     re-encoded with a synthetic HID pen descriptor (same ranges and\n"
    "                     resolution; vendor bytes, non-pen reports and bad frames are lost)\n"
    "  --samples N        with --decoded: stop after N samples\n"
    "%s\n"
    "Exit codes: 0 recorded, 2 bad usage or FILE not writable, 1 daemon not running, too old for\n"
    "raw reports (see --decoded), no such device, events lost (FILE has gaps), or failed.\n";

} // namespace

int record_fail(const std::string& message, int code) {
  std::fprintf(stderr, "penshape record: %s\n", message.c_str());
  return code;
}

std::optional<v1::ListDevicesResponse> list_devices(v1::Live::Stub& stub,
                                                    const RecordOptions& options, int* exit_code) {
  v1::ListDevicesResponse devices;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
  const grpc::Status status = stub.ListDevices(&context, {}, &devices);
  if (!status.ok()) {
    const RpcFailure f = describe_rpc_failure(status, "ListDevices", options.address);
    *exit_code = record_fail(f.message, f.exit_code);
    return std::nullopt;
  }
  return devices;
}

std::optional<v1::DeviceInfo> choose_device(v1::Live::Stub& stub, const RecordOptions& options,
                                            int* exit_code) {
  const std::optional<v1::ListDevicesResponse> devices = list_devices(stub, options, exit_code);
  if (!devices) return std::nullopt;
  const v1::DeviceInfo* device = nullptr;
  for (const auto& d : devices->devices()) {
    if (!options.device || d.id() == *options.device) device = &d;
  }
  if (options.device && device == nullptr) {
    *exit_code = record_fail(
        "no device '" + *options.device + "' is attached (see `penshape devices`)", kExitInternal);
    return std::nullopt;
  }
  if (!options.device && devices->devices_size() != 1) {
    *exit_code = record_fail(devices->devices_size() == 0
                                 ? "no tablets are attached to penshaped at " + options.address
                                 : "several tablets are attached: choose one with --device ID",
                             kExitInternal);
    return std::nullopt;
  }
  return *device;
}

int run_record(std::span<const std::string_view> args) {
  const ParsedArgs parsed(
      args, live_arg_spec({.flags = {"--wait", "--decoded"},
                           .options = {"--device", "--strokes", "--samples", "--duration"}}));
  if (parsed.flag("--help")) {
    std::printf(kHelp, kLiveOptionsHelp);
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) {
    throw UsageError(parsed.positionals().empty() ? "missing the output FILE"
                                                  : "expected one output FILE");
  }
  RecordOptions options;
  options.path = parsed.positionals().front();
  options.address = daemon_address(parsed);
  options.device = parsed.value("--device");
  options.max_strokes = parsed.positive_integer("--strokes");
  options.max_samples = parsed.positive_integer("--samples");
  options.duration_seconds = parsed.number("--duration");
  options.wait = parsed.flag("--wait");
  if (options.duration_seconds &&
      (*options.duration_seconds <= 0 || *options.duration_seconds > 1e7)) {
    throw UsageError("option '--duration' needs a number of seconds > 0");
  }
  const bool decoded = parsed.flag("--decoded");
  if (options.max_samples && !decoded) {
    throw UsageError("option '--samples' counts decoded samples: it goes with --decoded");
  }
  if (options.wait && decoded) {
    throw UsageError("option '--wait' needs raw reports: it does not go with --decoded");
  }

  CancelOnSignal cancel; // before any gRPC thread exists
  try {
    auto stub = v1::Live::NewStub(connect_to_daemon(options.address));
    return decoded ? record_decoded(*stub, options, cancel) : record_raw(*stub, options, cancel);
  } catch (const DaemonUnavailable& e) {
    return record_fail(e.what(), kExitInternal);
  }
}

} // namespace penshape::cli
