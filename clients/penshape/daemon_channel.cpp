#include "daemon_channel.hpp"

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>
#include <sys/stat.h>

#include <cstdlib>
#include <fstream>

#include "command.hpp"

namespace penshape::cli {
namespace {

std::string not_running(const std::string& address) {
  return "penshaped is not running at " + address +
         " (start it with `penshaped`, or point --socket/--address at a running one)";
}

// Whether a unix-abstract name is bound by anyone: Linux lists them as "@name" in /proc/net/unix.
// Unknown (true) when that file cannot be read.
bool abstract_socket_may_exist(const std::string& name) {
  std::ifstream table("/proc/net/unix");
  if (!table) return true;
  std::string line;
  const std::string wanted = "@" + name;
  while (std::getline(table, line)) {
    if (line.size() >= wanted.size() &&
        line.compare(line.size() - wanted.size(), wanted.size(), wanted) == 0) {
      return true;
    }
  }
  return false;
}

// Large messages: strokes and ink polygons of a long session fit well within this.
constexpr int kMaxReceiveBytes = 64 * 1024 * 1024;

} // namespace

ArgSpec live_arg_spec(ArgSpec own) {
  own.options.insert("--socket");
  own.options.insert("--address");
  own.flags.insert("--help");
  return own;
}

std::string default_daemon_address() {
  const char* runtime = std::getenv("XDG_RUNTIME_DIR");
  const std::string dir = (runtime != nullptr && *runtime != '\0') ? runtime : "/tmp";
  return "unix:" + dir + "/penshape.sock";
}

std::string daemon_address(const ParsedArgs& args) {
  const auto socket = args.value("--socket");
  const auto address = args.value("--address");
  if (socket && address) throw UsageError("give either --socket or --address, not both");
  if (socket) {
    if (socket->empty()) throw UsageError("option '--socket' needs a path");
    return "unix:" + *socket;
  }
  if (address) {
    if (address->empty()) throw UsageError("option '--address' needs an address");
    return *address;
  }
  return default_daemon_address();
}

std::shared_ptr<grpc::Channel> connect_to_daemon(const std::string& address,
                                                 std::chrono::milliseconds wait) {
  // A missing socket file is certain: say so at once instead of waiting for the timeout.
  if (address.rfind("unix:", 0) == 0) {
    struct stat st {};
    if (::stat(address.c_str() + 5, &st) != 0 || !S_ISSOCK(st.st_mode)) {
      throw DaemonUnavailable(not_running(address));
    }
  }
  if (address.rfind("unix-abstract:", 0) == 0 && !abstract_socket_may_exist(address.substr(14))) {
    throw DaemonUnavailable(not_running(address));
  }
  grpc::ChannelArguments arguments;
  arguments.SetMaxReceiveMessageSize(kMaxReceiveBytes);
  auto channel = grpc::CreateCustomChannel(address, grpc::InsecureChannelCredentials(), arguments);
  if (!channel->WaitForConnected(std::chrono::system_clock::now() + wait)) {
    throw DaemonUnavailable(not_running(address));
  }
  return channel;
}

RpcFailure describe_rpc_failure(const grpc::Status& status, std::string_view call,
                                const std::string& address) {
  if (status.error_code() == grpc::StatusCode::UNAVAILABLE) {
    return {kExitInternal, not_running(address) + ": " + status.error_message()};
  }
  const int code =
      status.error_code() == grpc::StatusCode::INVALID_ARGUMENT ? kExitBadInput : kExitInternal;
  return {code, std::string(call) + " failed (gRPC status " +
                    std::to_string(static_cast<int>(status.error_code())) +
                    "): " + status.error_message()};
}

} // namespace penshape::cli
