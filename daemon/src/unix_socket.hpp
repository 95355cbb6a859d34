#pragma once
// The daemon's unix socket: owner-only, never stolen from a running daemon, removed at exit.
#include <string>

namespace penshape::daemon {

// The filesystem path of a "unix:PATH" address; "" for other addresses (abstract, TCP).
std::string unix_socket_path(const std::string& address);

// Throws std::runtime_error when a daemon already answers on `path` (gRPC would otherwise unlink
// its socket and take over). A stale socket file is left for gRPC to replace.
void refuse_if_in_use(const std::string& path);

// chmod 0600; throws std::runtime_error on failure.
void make_owner_only(const std::string& path);

} // namespace penshape::daemon
