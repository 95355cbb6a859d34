#pragma once
// `penshape record`'s two ways of recording, behind one command line (record_command.cpp):
//  - record_raw (record_command_raw.cpp): the device's own descriptor and raw reports, as
//    penshaped forwards them (include_raw_reports) — the default;
//  - record_decoded (record_command_decoded.cpp): decoded samples re-encoded with a synthetic
//    descriptor (--decoded), for daemons that predate raw reports.
#include <cstdint>
#include <optional>
#include <string>

#include "cancel_on_signal.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace penshape::cli {

struct RecordOptions {
  std::string path;    // the output FILE
  std::string address; // the daemon's gRPC address
  std::optional<std::string> device;
  std::optional<std::uint64_t> max_strokes;
  std::optional<std::uint64_t> max_samples; // --decoded only
  std::optional<double> duration_seconds;
  bool wait = false; // wait for a tablet to attach (raw only)
};

// Prints "penshape record: MESSAGE" to stderr and returns `code`.
int record_fail(const std::string& message, int code);

// The devices attached to penshaped (ListDevices, 10 s deadline). Returns nullopt after printing
// why the call failed and setting `*exit_code`.
std::optional<v1::ListDevicesResponse> list_devices(v1::Live::Stub& stub,
                                                    const RecordOptions& options, int* exit_code);

// The attached device to record: the one named by --device, or the only one attached. Returns
// nullopt after printing why not (no tablet, several, no such device, the call failed) and
// setting `*exit_code`.
std::optional<v1::DeviceInfo> choose_device(v1::Live::Stub& stub, const RecordOptions& options,
                                            int* exit_code);

int record_raw(v1::Live::Stub& stub, const RecordOptions& options, CancelOnSignal& cancel);
int record_decoded(v1::Live::Stub& stub, const RecordOptions& options, CancelOnSignal& cancel);

} // namespace penshape::cli
