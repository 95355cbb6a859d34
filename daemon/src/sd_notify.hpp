#pragma once
// The systemd notification protocol (sd_notify(3)) without libsystemd: one datagram to the
// AF_UNIX socket named by $NOTIFY_SOCKET (a path, or "@name" for the abstract namespace).
#include <string>

namespace penshape::daemon {

// Sends `state` (e.g. "READY=1\nSTATUS=listening") when NOTIFY_SOCKET is set. Returns false when
// it is unset or the send failed (not an error outside systemd).
bool sd_notify_state(const std::string& state);

} // namespace penshape::daemon
