#pragma once
// The live subcommands: they talk to a running penshaped over gRPC.
#include <span>
#include <string_view>

namespace penshape::cli {
int run_devices(std::span<const std::string_view> args); // devices_command.cpp
int run_watch(std::span<const std::string_view> args);   // watch_command.cpp
int run_record(std::span<const std::string_view> args);  // record_command.cpp
} // namespace penshape::cli
