// `penshape devices`: the tablets penshaped reads now.
#include <cstdio>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "daemon_channel.hpp"
#include "json_writer.hpp"
#include "live_commands.hpp"
#include "live_event_text.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace penshape::cli {

int run_devices(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, live_arg_spec({.flags = {"--json"}, .options = {}}));
  if (parsed.flag("--help")) {
    std::printf(
        "usage: penshape devices [--json] [--socket PATH | --address ADDR]\n\n"
        "Lists the tablets penshaped reads now (and recordings it replays as if live).\n"
        "One line per device: id, vendor:product, name, active area, source.\n\n"
        "options:\n"
        "  --json             one JSON object per device: id, settings_key, name, vendor_id,\n"
        "                     product_id, bus, x_max, y_max, pressure_max, x_resolution,\n"
        "                     y_resolution (units/mm), has_tilt, width_mm, height_mm, source,\n"
        "                     replay\n%s\n"
        "Exit codes: 0 ok (also with no devices), 2 bad usage, 1 daemon not running or failed.\n",
        kLiveOptionsHelp);
    return kExitOk;
  }
  if (!parsed.positionals().empty()) {
    throw UsageError("unexpected argument '" + parsed.positionals().front() + "'");
  }
  const std::string address = daemon_address(parsed);
  try {
    auto stub = v1::Live::NewStub(connect_to_daemon(address));
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
    v1::ListDevicesResponse response;
    const grpc::Status status = stub->ListDevices(&context, {}, &response);
    if (!status.ok()) {
      const RpcFailure failure = describe_rpc_failure(status, "ListDevices", address);
      std::fprintf(stderr, "penshape devices: %s\n", failure.message.c_str());
      return failure.exit_code;
    }
    if (parsed.flag("--json")) {
      for (const auto& device : response.devices()) {
        JsonWriter json;
        write_device_json(json, device);
        std::puts(json.str().c_str());
      }
    } else if (response.devices_size() == 0) {
      std::printf("no tablets attached (penshaped at %s)\n", address.c_str());
    } else {
      for (const auto& device : response.devices()) std::puts(device_line(device).c_str());
    }
    return kExitOk;
  } catch (const DaemonUnavailable& e) {
    std::fprintf(stderr, "penshape devices: %s\n", e.what());
    return kExitInternal;
  }
}

} // namespace penshape::cli
