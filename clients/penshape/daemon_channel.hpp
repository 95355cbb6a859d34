#pragma once
// How the live subcommands (devices, watch, record) reach penshaped: the --socket/--address
// options, the default address, the connection check, and what a failed call tells the user.
#include <grpcpp/channel.h>
#include <grpcpp/support/status.h>

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "args.hpp"

namespace penshape::cli {

// Help text for the options every live subcommand takes.
inline constexpr const char* kLiveOptionsHelp =
    "  --socket PATH      the daemon's unix socket (default: $XDG_RUNTIME_DIR/penshape.sock)\n"
    "  --address ADDR     a gRPC address instead: unix:PATH, unix-abstract:NAME or HOST:PORT\n"
    "  --help             this text\n";

// `own` plus --socket, --address and --help.
ArgSpec live_arg_spec(ArgSpec own);

// The daemon's default address, the same rule as penshaped's: unix:$XDG_RUNTIME_DIR/penshape.sock
// (/tmp when XDG_RUNTIME_DIR is unset or empty).
std::string default_daemon_address();

// The address the options name; UsageError when both are given or one is empty.
std::string daemon_address(const ParsedArgs& args);

// penshaped does not answer at `address`; the message says so and how to fix it.
struct DaemonUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A channel that is connected to the daemon. Throws DaemonUnavailable when a unix socket does not
// exist or nothing answers within `wait`.
std::shared_ptr<grpc::Channel> connect_to_daemon(
    const std::string& address, std::chrono::milliseconds wait = std::chrono::seconds(3));

// The exit code for a failed call and a message naming the call ("ListDevices: ..."); a daemon
// that went away reads as DaemonUnavailable's message.
struct RpcFailure {
  int exit_code;
  std::string message;
};
RpcFailure describe_rpc_failure(const grpc::Status& status, std::string_view call,
                                const std::string& address);

} // namespace penshape::cli
