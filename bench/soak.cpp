// Soak: the real penshaped under steady load for N minutes, watched from outside. The daemon
// (a child process) replays every bundled recording again and again (--replay ... --replay-loop);
// 8 gRPC subscribers take every event (samples and raw reports too), one of them reading slowly
// through a small queue so that it must lose events; one client calls Deconstruct (with
// simplification) over and over. After a warm-up the daemon's resident memory, open file
// descriptors and threads are read from /proc, and again at the end under the same load; then the
// clients leave and the threads are read once more.
//
// It fails (exit 1) when RSS grew by more than 10%, when fds grew, when the daemon keeps more
// threads once the clients have left than it had under load at the start (gRPC's server grows
// and shrinks its pool with the calls in flight, so under load a thread more or less is not a
// leak; one left behind when the calls are gone is), when a subscriber
// saw a gap in the event sequence that its EventsDropped notices do not account for (an event
// lost without notice), or when the daemon delivered nothing or died.
//
//   build/release/bench/soak --penshaped build/release/daemon/penshaped [--minutes 2]
//                            [--recordings recordings] [--warmup-seconds 20]
#include <grpcpp/grpcpp.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "penshape/v1/geometry.grpc.pb.h"
#include "penshape/v1/live.grpc.pb.h"

namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;
namespace v1 = penshape::v1;

constexpr int kSubscribers = 8; // the last one is the slow one

struct Options {
  std::string penshaped;
  std::string recordings = PENSHAPE_SOURCE_DIR "/recordings";
  double minutes = 2;
  double warmup_seconds = 20;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--penshaped") {
      o.penshaped = argv[i + 1];
    } else if (key == "--recordings") {
      o.recordings = argv[i + 1];
    } else if (key == "--minutes") {
      o.minutes = std::atof(argv[i + 1]);
    } else if (key == "--warmup-seconds") {
      o.warmup_seconds = std::atof(argv[i + 1]);
    } else {
      throw std::invalid_argument("unknown option " + key);
    }
  }
  if ((argc - 1) % 2 != 0) throw std::invalid_argument("options take a value each");
  if (o.penshaped.empty()) throw std::invalid_argument("--penshaped PATH is required");
  if (!(o.minutes > 0) || !(o.warmup_seconds >= 0)) throw std::invalid_argument("bad durations");
  return o;
}

// The daemon's footprint, read from /proc.
struct Footprint {
  long rss_kb = 0;
  long threads = 0;
  long fds = 0;
};

Footprint footprint(pid_t pid) {
  Footprint f;
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      status >> f.rss_kb;
    } else if (key == "Threads:") {
      status >> f.threads;
    }
  }
  for (const auto& e : fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd")) {
    (void)e;
    ++f.fds;
  }
  return f;
}

// The real daemon as a child process; SIGTERM and reaped when destroyed.
class Daemon {
 public:
  Daemon(const Options& o, const std::string& address) {
    std::vector<std::string> args{o.penshaped, "--listen", address, "--replay-loop"};
    for (const auto& e : fs::directory_iterator(o.recordings)) {
      if (e.path().extension() == ".hidrec") {
        args.push_back("--replay");
        args.push_back(e.path().string());
      }
    }
    pid_ = fork();
    if (pid_ == 0) {
      std::vector<char*> argv;
      argv.reserve(args.size() + 1);
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
  }
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;
  ~Daemon() { stop(); }
  [[nodiscard]] pid_t pid() const { return pid_; }
  [[nodiscard]] bool alive() const { return pid_ > 0 && kill(pid_, 0) == 0 && !reaped(); }
  int stop() {
    if (pid_ <= 0) return status_;
    kill(pid_, SIGTERM);
    int st = 0;
    waitpid(pid_, &st, 0);
    pid_ = -1;
    status_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
    return status_;
  }

 private:
  [[nodiscard]] bool reaped() const {
    int st = 0;
    return waitpid(pid_, &st, WNOHANG) == pid_;
  }
  pid_t pid_ = -1;
  int status_ = 0;
};

// One subscriber's tally: events by sequence, and what the drop notices account for.
struct Tally {
  std::atomic<std::uint64_t> delivered{0};
  std::atomic<std::uint64_t> shapes{0};
  std::atomic<std::uint64_t> dropped_notified{0};
  std::atomic<std::uint64_t> sequence_gaps{0}; // events skipped in the sequence numbers
};

class Subscriber {
 public:
  Subscriber(const std::shared_ptr<grpc::Channel>& channel, bool slow)
      : stub_(v1::Live::NewStub(channel)), slow_(slow) {
    thread_ = std::thread([this] { run(); });
  }
  Subscriber(const Subscriber&) = delete;
  Subscriber& operator=(const Subscriber&) = delete;
  ~Subscriber() {
    context_.TryCancel();
    thread_.join();
  }
  const Tally& tally() const { return tally_; }
  [[nodiscard]] bool slow() const { return slow_; }

 private:
  void run() {
    v1::SubscribeRequest request;
    request.set_include_samples(true);
    // Every kind of event the daemon publishes here (raw reports bring the device events with
    // them), so that a gap in the sequence numbers can only be a drop.
    request.set_include_raw_reports(true);
    if (slow_) request.set_max_queued_events(16); // reads far slower than events arrive
    auto reader = stub_->Subscribe(&context_, request);
    v1::LiveEvent event;
    std::uint64_t last = 0;
    while (reader->Read(&event)) {
      if (event.has_dropped()) {
        tally_.dropped_notified += event.dropped().count();
        continue;
      }
      ++tally_.delivered;
      if (event.has_shape()) ++tally_.shapes;
      if (event.sequence() != 0) {
        if (last != 0 && event.sequence() > last + 1)
          tally_.sequence_gaps += event.sequence() - last - 1;
        last = event.sequence();
      }
      if (slow_) std::this_thread::sleep_for(20ms);
    }
    (void)reader->Finish();
  }

  std::unique_ptr<v1::Live::Stub> stub_;
  bool slow_;
  grpc::ClientContext context_;
  Tally tally_;
  std::thread thread_;
};

// A 24-vertex star, the Deconstruct calls' input: small enough for many calls a second.
v1::DeconstructRequest deconstruct_request() {
  v1::DeconstructRequest r;
  auto* ring = r.mutable_polygon()->add_polygons()->mutable_outer();
  for (int i = 0; i < 24; ++i) {
    const double a = 2 * M_PI * i / 24, radius = i % 2 == 0 ? 100 : 60;
    auto* p = ring->add_points();
    p->set_x(std::round(radius * std::cos(a)));
    p->set_y(std::round(radius * std::sin(a)));
  }
  r.mutable_radius()->set_value(6);
  r.mutable_tolerance()->set_value(3);
  r.set_simplify(true);
  return r;
}

class DeconstructLoad {
 public:
  explicit DeconstructLoad(const std::shared_ptr<grpc::Channel>& channel)
      : stub_(v1::Geometry::NewStub(channel)) {
    thread_ = std::thread([this] {
      const auto request = deconstruct_request();
      while (!stop_) {
        grpc::ClientContext context;
        context.set_deadline(std::chrono::system_clock::now() + 10s);
        v1::DeconstructResponse response;
        (stub_->Deconstruct(&context, request, &response).ok() ? ok_ : failed_)++;
        std::this_thread::sleep_for(50ms);
      }
    });
  }
  DeconstructLoad(const DeconstructLoad&) = delete;
  DeconstructLoad& operator=(const DeconstructLoad&) = delete;
  ~DeconstructLoad() {
    stop_ = true;
    thread_.join();
  }
  std::atomic<std::uint64_t> ok_{0}, failed_{0};

 private:
  std::unique_ptr<v1::Geometry::Stub> stub_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// The smallest of 6 readings a second apart: a replay's reader thread comes and goes with the
// recordings, and RSS breathes with the queues, so single readings at the start and the end may
// catch different phases; what a leak leaves behind shows in the minimum too.
Footprint settled_footprint(pid_t pid) {
  Footprint m = footprint(pid);
  for (int i = 0; i < 5; ++i) {
    std::this_thread::sleep_for(1s);
    const Footprint f = footprint(pid);
    m.rss_kb = std::min(m.rss_kb, f.rss_kb);
    m.threads = std::min(m.threads, f.threads);
    m.fds = std::min(m.fds, f.fds);
  }
  return m;
}

// Threads once every client has gone: gRPC lets its idle pollers exit, so wait (up to 20 s) for
// the count to come down to the reference before judging it.
long threads_after_clients_left(pid_t pid, long reference) {
  long threads = footprint(pid).threads;
  for (int i = 0; i < 20 && threads > reference; ++i) {
    std::this_thread::sleep_for(1s);
    threads = footprint(pid).threads;
  }
  return threads;
}

void print_footprint(const char* when, const Footprint& f) {
  std::printf("%-6s RSS %7.1f MB   fds %4ld   threads %3ld\n", when,
              static_cast<double>(f.rss_kb) / 1024.0, f.fds, f.threads);
}

} // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    o = parse(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr,
                 "soak: %s\nusage: soak --penshaped PATH [--minutes M] "
                 "[--recordings DIR] [--warmup-seconds S]\n",
                 e.what());
    return 2;
  }
  const std::string address = "unix-abstract:penshape-soak-" + std::to_string(getpid());
  Daemon daemon(o, address);
  auto channel = grpc::CreateChannel(address, grpc::InsecureChannelCredentials());
  if (!channel->WaitForConnected(std::chrono::system_clock::now() + 10s)) {
    std::fprintf(stderr, "soak: penshaped did not answer at %s\n", address.c_str());
    return 1;
  }
  std::vector<std::unique_ptr<Subscriber>> subscribers;
  for (int i = 0; i < kSubscribers; ++i) {
    // Each on its own channel, as separate apps would be. The slow one also takes a small HTTP/2
    // window, or gRPC would buffer megabytes for it in the client and the daemon's queue for it
    // would never fill.
    const bool slow = i == kSubscribers - 1;
    grpc::ChannelArguments args;
    if (slow) {
      args.SetInt(GRPC_ARG_HTTP2_BDP_PROBE, 0);
      args.SetInt(GRPC_ARG_HTTP2_STREAM_LOOKAHEAD_BYTES, 1024);
    }
    subscribers.push_back(std::make_unique<Subscriber>(
        grpc::CreateCustomChannel(address, grpc::InsecureChannelCredentials(), args), slow));
  }
  auto deconstruct = std::make_unique<DeconstructLoad>(channel);

  std::printf(
      "soak: penshaped (pid %d) replaying the bundled recordings in a loop, %d "
      "subscribers (1 slow), Deconstruct calls; %.1f min after %.0f s of warm-up\n",
      daemon.pid(), kSubscribers, o.minutes, o.warmup_seconds);
  std::this_thread::sleep_for(std::chrono::duration<double>(o.warmup_seconds));
  const Footprint start = settled_footprint(daemon.pid());
  print_footprint("start", start);
  // The footprint every 30 s on the way, to tell a plateau from a steady climb.
  const auto until =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(o.minutes * 60);
  while (std::chrono::steady_clock::now() + 30s < until && daemon.alive()) {
    std::this_thread::sleep_for(30s);
    if (daemon.alive()) print_footprint("  now", footprint(daemon.pid()));
  }
  std::this_thread::sleep_until(until);
  const bool alive = daemon.alive();
  const Footprint end = alive ? settled_footprint(daemon.pid()) : Footprint{};
  print_footprint("end", end);

  bool failed = false;
  const auto fail = [&failed](const char* why) {
    failed = true;
    std::printf("FAIL: %s\n", why);
  };
  if (!alive) fail("penshaped died during the soak");
  std::printf("%-11s %10s %8s %14s %14s\n", "subscriber", "delivered", "shapes", "drop notices",
              "unaccounted");
  std::uint64_t shapes = 0;
  for (std::size_t i = 0; i < subscribers.size(); ++i) {
    const Tally& t = subscribers[i]->tally();
    const std::uint64_t gaps = t.sequence_gaps, noticed = t.dropped_notified;
    const std::uint64_t unaccounted = gaps > noticed ? gaps - noticed : 0;
    std::printf("%-11s %10llu %8llu %14llu %14llu\n",
                (std::to_string(i + 1) + (subscribers[i]->slow() ? " (slow)" : "")).c_str(),
                static_cast<unsigned long long>(t.delivered.load()),
                static_cast<unsigned long long>(t.shapes.load()),
                static_cast<unsigned long long>(noticed),
                static_cast<unsigned long long>(unaccounted));
    if (unaccounted > 0) fail("a subscriber lost events without a drop notice");
    shapes += t.shapes;
  }
  std::printf("Deconstruct calls: %llu ok, %llu failed\n",
              static_cast<unsigned long long>(deconstruct->ok_.load()),
              static_cast<unsigned long long>(deconstruct->failed_.load()));
  const double rss_growth =
      start.rss_kb > 0 ? static_cast<double>(end.rss_kb) / static_cast<double>(start.rss_kb) - 1
                       : 0;
  std::printf("RSS growth %+.1f%% (limit +10%%), fds %+ld, threads %+ld\n", 100 * rss_growth,
              end.fds - start.fds, end.threads - start.threads);
  if (alive && rss_growth > 0.10) fail("RSS grew by more than 10%");
  if (alive && end.fds > start.fds) fail("open fds grew");
  if (shapes == 0) fail("no shape reached any subscriber");
  if (deconstruct->ok_ == 0) fail("no Deconstruct call succeeded");
  deconstruct.reset();
  subscribers.clear();
  if (alive && daemon.alive()) {
    const long idle = threads_after_clients_left(daemon.pid(), start.threads);
    std::printf("threads once the clients left: %ld (under load at the start: %ld)\n", idle,
                start.threads);
    if (idle > start.threads) fail("threads left behind after the clients left");
  }
  if (daemon.stop() != 0) fail("penshaped did not exit with 0 on SIGTERM");
  std::printf(failed ? "soak: FAILED\n" : "soak: flat\n");
  return failed ? 1 : 0;
}
