#pragma once
// What the benchmarks share: latency percentiles and medians, the process's and the thread's CPU
// time and memory, a scratch directory for sockets, and the `[--seconds N] [--json]` command line.
#include <unistd.h>

#include <ctime>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace penshape::bench {

struct Percentiles {
  double p50 = 0, p99 = 0, max = 0;
  std::size_t n = 0;
};

// Nearest-rank percentiles (p99 of 100 values is the largest but one).
inline Percentiles percentiles(std::vector<double> v) {
  Percentiles p;
  p.n = v.size();
  if (v.empty()) return p;
  std::sort(v.begin(), v.end());
  auto at = [&](double q) {
    return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
  };
  p.p50 = at(0.50);
  p.p99 = at(0.99);
  p.max = v.back();
  return p;
}

// The median (the upper one of an even count); 0 when empty.
inline double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// This thread's CPU time: what a shared machine's other load inflates least.
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

struct ProcessUsage {
  double cpu_seconds = 0; // user + system, all threads
  long rss_kb = 0;        // resident now
  long peak_rss_kb = 0;   // resident at most so far (VmHWM)
};

inline ProcessUsage process_usage() {
  ProcessUsage u;
  std::ifstream stat("/proc/self/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), {});
  // Fields after the command name (which may contain spaces) start after the last ')'.
  std::istringstream fields(text.substr(text.rfind(')') + 2));
  std::string field;
  unsigned long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) utime = std::stoull(field);
    if (i == 15) stime = std::stoull(field);
  }
  u.cpu_seconds = static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) u.rss_kb = std::stol(line.substr(6));
    if (line.rfind("VmHWM:", 0) == 0) u.peak_rss_kb = std::stol(line.substr(6));
  }
  return u;
}

// A fresh private directory under the system's temp dir (for the benchmark's unix socket).
inline std::string make_scratch_dir() {
  std::string dir = (std::filesystem::temp_directory_path() / "penshape-bench-XXXXXX").string();
  if (::mkdtemp(dir.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return dir;
}

struct SecondsArgs {
  double seconds = 0;
  bool json = false;
};

// `name [--seconds N] [--json]`, N in (0, 600]; prints the usage and returns nothing on bad input.
inline std::optional<SecondsArgs> parse_seconds_args(int argc, char** argv, const char* name,
                                                     double default_seconds) {
  SecondsArgs args{default_seconds, false};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--json") {
      args.json = true;
    } else if (arg == "--seconds" && i + 1 < argc) {
      args.seconds = std::atof(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--seconds N] [--json]\n", name);
      return std::nullopt;
    }
  }
  if (!(args.seconds > 0 && args.seconds <= 600)) {
    std::fprintf(stderr, "%s: --seconds must be in (0, 600]\n", name);
    return std::nullopt;
  }
  return args;
}

} // namespace penshape::bench
