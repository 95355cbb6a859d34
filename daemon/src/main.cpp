// penshaped: the penshape daemon. Serves the penshape.v1 API on a unix socket.
#include <pthread.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <future>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "log.hpp"
#include "penshape/core/version.hpp"
#include "penshape/daemon/config.hpp"
#include "penshape/daemon/device_manager_source.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/drivers/recording.hpp"
#include "replay_file.hpp"
#include "sd_notify.hpp"
#include "sources.hpp"

namespace {

// The thread that waits for SIGINT/SIGTERM and shuts the server down. Should anything fail while
// it waits, its destructor signals it and joins, so a failure stops the server cleanly (socket
// removed) instead of destroying a joinable thread, which would abort the process.
struct SignalWaiter {
  explicit SignalWaiter(std::function<void()> body) : thread(std::move(body)) {}
  SignalWaiter(const SignalWaiter&) = delete;
  SignalWaiter& operator=(const SignalWaiter&) = delete;
  ~SignalWaiter() {
    if (!thread.joinable()) return;
    // It sigwait()s for SIGTERM: the signal wakes it, and it returns.
    pthread_kill(thread.native_handle(), SIGTERM); // NOLINT(bugprone-bad-signal-to-kill-thread)
    thread.join();
  }
  std::thread thread;
};

constexpr const char* kUsage = R"(usage: penshaped [options]

The penshape daemon: reads pen tablets, recognizes the shapes drawn, and serves the penshape.v1
gRPC API (Geometry, Live, Config, Info, grpc.health.v1 and server reflection).

options:
  --config FILE              read settings and limits from FILE (format: see the README or
                             daemon/include/penshape/daemon/config.hpp). Default:
                             $XDG_CONFIG_HOME/penshape/penshaped.conf if it exists, else the
                             built-in defaults
  --listen ADDRESS           gRPC address: unix:PATH, unix-abstract:NAME or HOST:PORT
                             (default: unix:$XDG_RUNTIME_DIR/penshape.sock, owner-only)
  --tcp HOST:PORT            also listen on TCP; loopback hosts only unless
  --tcp-allow-non-loopback   is given too
  --replay FILE              replay a recording (hid-recorder format) at its recorded pace as
                             the only tablet, instead of the tablets attached to this machine;
                             given more than once, the recordings play one after another
  --replay-delay SECONDS     wait this long after startup before replaying (default 0)
  --replay-loop              play the recordings again and again until stopped (demos, soak)
  --help                     this text
  --version                  the version

Logs go to stderr. Stops gracefully on SIGINT or SIGTERM: strokes in progress finish and are
delivered, then the socket is removed. Tells systemd when it is ready (Type=notify).
exit codes: 0 stopped cleanly, 2 bad command line or config, 1 could not start.
)";

struct CommandLine {
  std::string config_path;
  std::string listen;
  std::string tcp;
  bool tcp_allow_non_loopback = false;
  std::vector<std::string> replays;
  double replay_delay_seconds = 0;
  bool replay_loop = false;
};

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

using penshape::daemon::log;
using penshape::daemon::LogLevel;

bool stop_requested(const std::shared_future<void>& stopped) {
  return stopped.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

// Plays the recordings one after another, each to its end (again and again with --replay-loop),
// until they are done or the daemon stops.
void play_recordings(penshape::daemon::DeviceManagerSource& source,
                     const std::vector<penshape::drivers::Recording>& recordings,
                     const CommandLine& cli, const std::shared_future<void>& stopped) {
  do {
    for (std::size_t i = 0; i < recordings.size() && !stop_requested(stopped); ++i) {
      log(LogLevel::kInfo, "replaying " + cli.replays[i] + " at its recorded pace");
      source.replay(recordings[i], penshape::drivers::ReplaySpeed::kOriginal);
      while (!source.wait_until_idle(std::chrono::milliseconds(200))) {
        if (stop_requested(stopped)) return;
      }
    }
  } while (cli.replay_loop && !stop_requested(stopped));
}

// $XDG_CONFIG_HOME/penshape/penshaped.conf (~/.config when unset) when that file exists, else "".
std::string default_config_path() {
  std::string base;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg != nullptr && *xdg != '\0') {
    base = xdg;
  } else if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    base = std::string(home) + "/.config";
  } else {
    return "";
  }
  const std::string path = base + "/penshape/penshaped.conf";
  return ::access(path.c_str(), F_OK) == 0 ? path : "";
}

// Reads the command line into `cli` with CLI11. Returns an exit code when the program ends here
// (--help, --version: 0; a bad command line: 2 with the message on stderr), else nullopt.
std::optional<int> parse_command_line(int argc, char** argv, CommandLine& cli) {
  CLI::App app("penshaped");
  app.set_help_flag(); // the help is kUsage, the man page's source
  app.allow_extras();  // unknown arguments are named in our own message below
  bool help = false;
  bool version = false;
  std::string delay;
  app.add_flag("-h,--help", help);
  app.add_flag("--version", version);
  app.add_option("--config", cli.config_path)->take_last();
  app.add_option("--listen", cli.listen)->take_last();
  app.add_option("--tcp", cli.tcp)->take_last();
  app.add_flag("--tcp-allow-non-loopback", cli.tcp_allow_non_loopback);
  app.add_option("--replay", cli.replays)->expected(1)->take_all()->allow_extra_args(false);
  app.add_option("--replay-delay", delay)->take_last();
  app.add_flag("--replay-loop", cli.replay_loop);
  // A flag takes no value: CLI11 would read `--replay-loop=true` as the flag.
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const std::string_view name = arg.substr(0, arg.find('='));
    if (name.size() < arg.size() && name.starts_with("-") &&
        app.get_option_no_throw(std::string(name)) != nullptr &&
        app.get_option_no_throw(std::string(name))->get_expected_min() == 0) {
      std::fprintf(stderr, "penshaped: unknown or incomplete option '%s' (see --help)\n", argv[i]);
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // A value missing after an option: CLI11 names the option before ':'.
    const std::string what = e.what();
    std::fprintf(stderr, "penshaped: unknown or incomplete option '%s' (see --help)\n",
                 what.substr(0, what.find(':')).c_str());
    return 2;
  }
  if (help) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (version) {
    std::printf("penshaped %s\n", penshape::version().c_str());
    return 0;
  }
  if (!app.remaining().empty()) {
    std::fprintf(stderr, "penshaped: unknown or incomplete option '%s' (see --help)\n",
                 app.remaining().front().c_str());
    return 2;
  }
  if (!delay.empty()) {
    char* end = nullptr;
    cli.replay_delay_seconds = std::strtod(delay.c_str(), &end);
    if (*end != '\0' || !(cli.replay_delay_seconds >= 0 && cli.replay_delay_seconds <= 3600)) {
      std::fprintf(stderr, "penshaped: --replay-delay wants seconds in [0, 3600], got '%s'\n",
                   delay.c_str());
      return 2;
    }
  }
  return std::nullopt;
}

// The config file and the command line's overrides; nullopt (logged) when they are bad.
std::optional<penshape::daemon::ServerOptions> server_options(CommandLine& cli) {
  penshape::daemon::ServerOptions options;
  try {
    if (cli.config_path.empty()) cli.config_path = default_config_path();
    if (!cli.config_path.empty()) {
      options.config = penshape::daemon::load_config_file(cli.config_path);
      log(LogLevel::kInfo, "config: " + cli.config_path);
    }
    if (!cli.tcp.empty()) options.config.tcp = cli.tcp;
    options.config.tcp_allow_non_loopback |= cli.tcp_allow_non_loopback;
    if (!options.config.tcp.empty()) {
      penshape::daemon::validate_tcp_address(options.config.tcp,
                                             options.config.tcp_allow_non_loopback);
    }
  } catch (const penshape::daemon::ConfigError& e) {
    log(LogLevel::kError, e.what());
    return std::nullopt;
  }
  options.address = !cli.listen.empty()              ? cli.listen
                    : !options.config.listen.empty() ? options.config.listen
                                                     : penshape::daemon::default_address();
  return options;
}

// With --replay the recordings are the only device (read and checked now, so a bad file is bad
// input before the daemon serves); nullopt (logged) when one is bad.
std::optional<std::vector<penshape::drivers::Recording>> load_recordings(const CommandLine& cli) {
  std::vector<penshape::drivers::Recording> recordings;
  for (const std::string& file : cli.replays) {
    try {
      recordings.push_back(penshape::daemon::load_replay_file(file));
    } catch (const penshape::daemon::BadReplayFile& e) {
      log(LogLevel::kError, std::string("--replay ") + e.what());
      return std::nullopt;
    }
  }
  if (cli.replay_loop && recordings.empty()) {
    std::fputs("penshaped: --replay-loop needs --replay FILE\n", stderr);
    return std::nullopt;
  }
  return recordings;
}

// Serves until SIGINT/SIGTERM: the recordings as the only tablet, or the tablets attached to this
// machine (with hotplug) when there are none. Returns the exit code.
int serve(const penshape::daemon::ServerOptions& options,
          const std::vector<penshape::drivers::Recording>& recordings, const CommandLine& cli) {
  const sigset_t signals = block_termination_signals();
  try {
    auto source = std::make_shared<penshape::daemon::DeviceManagerSource>(
        recordings.empty() ? penshape::drivers::make_hidraw_backend() : nullptr,
        options.config.device_sizes);
    penshape::daemon::ServerParts parts;
    parts.source = source;
    parts.geometry = penshape::daemon::make_geometry_backend();
    parts.analyzer = penshape::daemon::make_stroke_analyzer();
    if (!parts.geometry) log(LogLevel::kWarning, "no deconstruction engine in this build");
    if (!parts.analyzer) {
      log(LogLevel::kWarning, "no stroke analyzer in this build: strokes without shapes");
    }

    penshape::daemon::PenshapeServer server(options, parts);
    std::string where;
    for (const auto& a : server.addresses()) where += (where.empty() ? "" : ", ") + a;
    log(LogLevel::kInfo, "penshaped " + penshape::version() + " listening on " + where);
    penshape::daemon::sd_notify_state("READY=1\nSTATUS=listening on " + where);
    std::promise<void> stopping;
    std::shared_future<void> stopped = stopping.get_future().share();
    SignalWaiter waiter([&server, &stopping, signals] {
      int sig = 0;
      sigwait(&signals, &sig);
      log(LogLevel::kInfo, std::string(strsignal(sig)) + ", shutting down");
      penshape::daemon::sd_notify_state("STOPPING=1");
      stopping.set_value();
      server.shutdown();
    });
    // Clients get --replay-delay to connect before the first report; a signal cancels the replay.
    if (!recordings.empty() && stopped.wait_for(std::chrono::duration<double>(
                                   cli.replay_delay_seconds)) == std::future_status::timeout) {
      play_recordings(*source, recordings, cli, stopped);
    }
    server.wait();
    waiter.thread.join();
    log(LogLevel::kInfo, "stopped");
  } catch (const std::exception& e) {
    log(LogLevel::kError, e.what());
    return 1;
  }
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  CommandLine cli;
  if (const std::optional<int> done = parse_command_line(argc, argv, cli)) return *done;
  const std::optional<penshape::daemon::ServerOptions> options = server_options(cli);
  if (!options) return 2;
  const auto recordings = load_recordings(cli);
  if (!recordings) return 2;
  return serve(*options, *recordings, cli);
}
