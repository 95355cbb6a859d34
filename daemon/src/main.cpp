// penshaped: the penshape daemon. Serves the penshape.v1 API on a unix socket.
#include <unistd.h>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>
#include <thread>

#include "penshape/core/version.hpp"
#include "penshape/daemon/server.hpp"

namespace {

constexpr const char* kUsage = R"(usage: penshaped [--listen ADDRESS] [--help] [--version]

The penshape daemon: serves the penshape.v1 gRPC API (health and reflection included).

options:
  --listen ADDRESS   gRPC address: unix:PATH, unix-abstract:NAME or HOST:PORT
                     (default: unix:$XDG_RUNTIME_DIR/penshape.sock)
  --help             this text
  --version          the version

Stops gracefully on SIGINT or SIGTERM and removes its socket.
)";

// Blocks SIGINT/SIGTERM in every thread, then waits for one on a dedicated thread, so the
// shutdown runs in ordinary code rather than in a signal handler.
sigset_t block_termination_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  return set;
}

} // namespace

int main(int argc, char** argv) {
  std::string address = penshape::daemon::default_address();
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (arg == "--version") {
      std::printf("penshaped %s\n", penshape::version().c_str());
      return 0;
    }
    if (arg == "--listen" && i + 1 < argc) {
      address = argv[++i];
      continue;
    }
    std::fprintf(stderr, "penshaped: unknown or incomplete option '%s' (see --help)\n", argv[i]);
    return 2;
  }

  const sigset_t signals = block_termination_signals();
  try {
    penshape::daemon::PenshapeServer server({address});
    std::fprintf(stderr, "penshaped %s: listening on %s\n", penshape::version().c_str(),
                 address.c_str());
    std::thread waiter([&server, signals] {
      int sig = 0;
      sigwait(&signals, &sig);
      std::fprintf(stderr, "penshaped: %s, shutting down\n", strsignal(sig));
      server.shutdown();
    });
    server.wait();
    waiter.join();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "penshaped: %s\n", e.what());
    return 1;
  }
  // gRPC unlinks a stale socket on bind but not at exit.
  if (address.rfind("unix:", 0) == 0) ::unlink(address.substr(5).c_str());
  return 0;
}
