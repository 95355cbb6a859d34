// Scale of deconstruction and of its independent check (issue 15): wavy star polygons of 10,000,
// 50,000 and 200,000 vertices (generated here, deterministic), r = w/30, eps = r/2,
// delta = eps/8. Prints input validation alone, the whole deconstruct() call (validation + fast
// engine, no simplification) against the 0.7 s target at 200k (issue 26), and `penshape
// verify`'s checker; then the 200k star through the CLI, `penshape deconstruct` as a child
// process with its default simplification, its CPU time (user + system) beside the same target.
// First, validation's touching/crossing test on the star and on a comb (every edge spans every
// vertical line: the former x-range sweep's O(n²) case): the Shamos–Hoey sweep inside
// validate_region against the former test (bench/former_validation.hpp), in the same run; and
// validation of a polygon with thousands of holes (the nesting sweep).
//   scale_bench [--only N] [--former-offsets | --striped-offsets] [--validation] [--cli]
//               [--baseline-cli PATH]
// --cli runs only the CLI rows (its stages in this process, then the child process);
// --baseline-cli PATH runs a former build's penshape (e.g. main's) alternately beside it. --only N
// runs only the N-vertex star's deconstruction and prints its wall and thread CPU time (the shared
// build machine's load inflates wall time) and how many predicates needed the exact fallback, with
// the former offsets (one Clipper sweep per offset, ClipperOffset insets) and the striped ones
// (engine/fast/stripe_union.hpp) alternately, three times each; --former-offsets or
// --striped-offsets runs only that one, once (for profiling). The table's deconstruction is timed
// with both too. --validation prints only the validation table.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "engine/fast/certified.hpp"
#include "engine/fast/clipper_stage.hpp"
#include "former_validation.hpp"
#include "geometry/segment_sweep.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "penshape/core/simplify.hpp"
#include "penshape/core/validated_region.hpp"
#include "penshape/core/verify.hpp"

namespace {

// A star-shaped ring: increasing angles, so simple by construction.
penshape::PolygonSet wavy_star(int n) {
  std::mt19937 rng(static_cast<unsigned>(n));
  std::uniform_real_distribution<double> jitter(0.0, 0.8);
  std::uniform_real_distribution<double> bump(0.0, 3.0);
  penshape::Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + jitter(rng)) / n;
    const double r = 1000 + 40 * std::sin(7 * a) + bump(rng);
    ring.push_back(penshape::exact(penshape::PointD{std::round(r * std::cos(a) * 1024) / 1024,
                                                    std::round(r * std::sin(a) * 1024) / 1024}));
  }
  return {{{ring, {}}}};
}

// A comb of n vertices: horizontal teeth 1000 long, 2 apart, joined by a spine.
penshape::PolygonSet comb(int n) {
  const int teeth = (n - 2) / 4; // 4 per tooth, the last one short of one, and 2 for the spine
  penshape::Ring ring;
  ring.push_back({-1, 0});
  for (int i = 0; i < teeth; ++i) {
    ring.push_back({1000, 2 * i});
    ring.push_back({1000, 2 * i + 1});
    ring.push_back({0, 2 * i + 1});
    if (i + 1 < teeth) ring.push_back({0, 2 * i + 2});
  }
  ring.push_back({-1, 2 * teeth - 1});
  return {{{ring, {}}}};
}

// A square with n/4 - 1 square holes on a grid: the nesting check's worst case before its sweep
// (every hole was tested against every other hole).
penshape::PolygonSet holes(int n) {
  const int side = static_cast<int>(std::sqrt(n / 4.0));
  penshape::PolygonWithHoles p;
  const int extent = 4 * side + 2;
  p.outer = {{0, 0}, {extent, 0}, {extent, extent}, {0, extent}};
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const int x = 4 * i + 2, y = 4 * j + 2;
      p.holes.push_back({{x, y}, {x, y + 2}, {x + 2, y + 2}, {x + 2, y}});
    }
  }
  return {{p}};
}

// Thread CPU time: what the machine's other load does not inflate.
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) / 1e6;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The touching/crossing sweep alone on one ring (what the former test did), in ms: the ring
// layout validation uses (one event per vertex), or the segment layout it used before (one
// event per segment end, a neighbour test per pair), in thread CPU ms. `found` says whether it
// found a contact.
double sweep_ring_ms(const penshape::Ring& ring, bool ring_layout, bool& found) {
  std::vector<penshape::detail::FilteredPoint> pts;
  pts.reserve(ring.size());
  for (const auto& v : ring) pts.push_back(penshape::detail::filtered(v));
  const std::size_t n = ring.size();
  const double t0 = cpu_ms();
  if (ring_layout) {
    const std::vector<std::span<const penshape::detail::FilteredPoint>> rings{pts};
    found = penshape::detail::find_ring_contact(rings).has_value();
  } else {
    std::vector<penshape::detail::SweepSegment> segs;
    segs.reserve(n);
    for (std::size_t i = 0; i < n; ++i) segs.push_back({pts[i], pts[(i + 1) % n]});
    found = penshape::detail::find_forbidden_contact(segs, [n](std::size_t i, std::size_t j) {
              return (i + 1) % n == j || (j + 1) % n == i;
            }).has_value();
  }
  return cpu_ms() - t0;
}

// Issue 26: 200,000 vertices decided within this much CPU time, in deconstruct() and in the CLI.
constexpr double kTargetMs = 700.0;

// The star as x-y text (its coordinates are multiples of 1/1024: %.17g prints them exactly).
std::string write_star(const penshape::PolygonSet& q) {
  std::string path = (std::filesystem::temp_directory_path() /
                      ("scale_bench_star_" + std::to_string(getpid()) + ".txt"))
                         .string();
  std::ofstream out(path);
  char line[96];
  for (const auto& v : q.polygons[0].outer) {
    std::snprintf(line, sizeof line, "%.17g %.17g\n", v.x.get_d(), v.y.get_d());
    out << line;
  }
  return path;
}

// `penshape deconstruct FILE ...` as a child: its exit status, and its CPU ms (user + system).
int run_cli(const std::vector<std::string>& args, double& cpu) {
  std::fflush(stdout); // the child must not write our buffered table again
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    argv.reserve(args.size() + 1);
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (std::freopen("/dev/null", "w", stdout) == nullptr) _exit(127);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  cpu = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) * 1e3 +
        static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e3;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The 200k star through the CLI (reading, validation, decision, simplification, output), median
// CPU time of three runs; true when within the target. With `baseline` (a former build's
// penshape, e.g. main's), it runs alternately with this build's, in the same load, and is
// printed beside it.
bool cli_row(const std::string& baseline) {
  const penshape::PolygonSet q = wavy_star(200'000);
  const std::string path = write_star(q);
  const auto args = [&](const std::string& cli) {
    return std::vector<std::string>{cli,           "deconstruct", path,          "--radius", "69",
                                    "--tolerance", "34.5",        "--precision", "4.3125"};
  };
  std::vector<double> cpu(3);
  std::vector<double> former(3);
  int status = 0;
  int former_status = 0;
  for (std::size_t i = 0; i < cpu.size(); ++i) {
    if (!baseline.empty()) former_status = run_cli(args(baseline), former[i]);
    status = run_cli(args(PENSHAPE_CLI), cpu[i]);
  }
  std::filesystem::remove(path);
  std::sort(cpu.begin(), cpu.end());
  std::sort(former.begin(), former.end());
  const bool ok = status == 0 && cpu[1] <= kTargetMs;
  std::printf(
      "\npenshape deconstruct (CLI, default simplification), 200,000-vertex star, "
      "r = 69, eps = r/2, delta = eps/8:\n  exit %d, CPU %.1f ms median of 3 (target "
      "<= %.0f ms): %s\n",
      status, cpu[1], kTargetMs, ok ? "ok" : "FAIL");
  if (!baseline.empty()) {
    std::printf("  baseline %s: exit %d, CPU %.1f ms median of 3 (runs alternated)\n",
                baseline.c_str(), former_status, former[1]);
  }
  return ok;
}

// The CLI's stages on the 200k star in this process, thread CPU ms each: reading the text,
// validating it (once: deconstruct() takes the ValidatedRegion), deciding, simplifying, and the
// exact WKT of the answer; where `penshape deconstruct`'s time goes.
void cli_stages() {
  const penshape::PolygonSet star = wavy_star(200'000);
  const std::string path = write_star(star);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  double c0 = cpu_ms();
  penshape::PolygonSet q = penshape::read_polygon_text(text);
  const double read = cpu_ms() - c0;
  c0 = cpu_ms();
  const penshape::ValidatedRegion valid = penshape::ValidatedRegion::validate(std::move(q));
  const double validation = cpu_ms() - c0;
  c0 = cpu_ms();
  const penshape::DeconstructResult raw = penshape::deconstruct(
      valid, {penshape::Rational(69), penshape::Rational(69, 2), penshape::Rational(69, 16)});
  const double decision = cpu_ms() - c0;
  c0 = cpu_ms();
  const penshape::SimplifyResult simple = penshape::simplify_solution(valid.region(), raw);
  const double simplification = cpu_ms() - c0;
  c0 = cpu_ms();
  const std::size_t wkt = penshape::to_wkt(simple.result.solution).size();
  const double output = cpu_ms() - c0;
  // What the CLI calls: both in one, the simplifier reusing the decision's work (issue 26).
  c0 = cpu_ms();
  const penshape::SimplifyResult both = penshape::deconstruct_simplified(
      valid, {penshape::Rational(69), penshape::Rational(69, 2), penshape::Rational(69, 16)});
  const double together = cpu_ms() - c0;
  std::printf(
      "\nthe CLI's stages in this process (200,000-vertex star, thread CPU ms):\n"
      "  read text %.1f | validation (once) %.1f | deconstruct %.1f (%s) | simplification %.1f "
      "(%zu -> %zu vertices) | WKT %.1f (%zu chars) | total %.1f\n"
      "  deconstruct + simplification %.1f, deconstruct_simplified (reusing the decision's "
      "grid, Q_s, walk) %.1f (%s, %zu vertices) | total with it %.1f\n",
      read, validation, decision, penshape::to_string(raw.answer), simplification,
      simple.raw_vertices, simple.solution_vertices, output, wkt,
      read + validation + decision + simplification + output, decision + simplification, together,
      penshape::to_string(both.result.answer), both.solution_vertices,
      read + validation + together + output);
}

} // namespace

void validation_table() {
  std::printf(
      "validation: validate_region (all checks) and its touching/crossing test alone\n"
      "(Shamos-Hoey sweep: ring layout, one event per vertex; segment layout, one per segment\n"
      "end, as validation ran it before) vs the former x-range sweep (crossings only), same run;\n"
      "thread CPU ms\n");
  std::printf("%6s %8s | %13s | %8s | %11s | %10s | %7s\n", "shape", "vertices", "validation ms",
              "sweep ms", "segments ms", "former ms", "speedup");
  for (const bool is_comb : {false, true}) {
    for (const int n : {10'000, 50'000, 200'000}) {
      const penshape::PolygonSet q = is_comb ? comb(n) : wavy_star(n);
      const double t0 = cpu_ms();
      penshape::validate_region(q);
      const double whole = cpu_ms() - t0;
      bool found = false;
      bool found_segments = false;
      const double sweep = sweep_ring_ms(q.polygons[0].outer, true, found);
      const double segments = sweep_ring_ms(q.polygons[0].outer, false, found_segments);
      found = found || found_segments;
      // The former test is quadratic on the comb: 200k would take minutes.
      if (is_comb && n > 50'000) {
        std::printf("%6s %8zu | %13.1f | %8.1f | %11.1f | %10s | %7s\n", "comb", q.vertex_count(),
                    whole, sweep, segments, "skipped", "O(n^2)");
        continue;
      }
      const double t1 = cpu_ms();
      const bool contact = penshape::bench::former_ring_has_contact(q.polygons[0].outer);
      const double former = cpu_ms() - t1;
      std::printf("%6s %8zu | %13.1f | %8.1f | %11.1f | %10.1f | %6.1fx%s\n",
                  is_comb ? "comb" : "star", q.vertex_count(), whole, sweep, segments, former,
                  former / sweep, contact || found ? " (a contact found in valid input!)" : "");
    }
  }
  // Nesting: validate_region on a polygon with many holes (the former pairwise test was
  // O(n · holes): 10^4 holes meant 10^9 point tests).
  for (const int n : {10'000, 50'000, 200'000}) {
    const penshape::PolygonSet q = holes(n);
    const double t0 = cpu_ms();
    penshape::validate_region(q);
    std::printf("%6s %8zu | %13.1f | (%zu holes: nesting by one sweep)\n", "holes",
                q.vertex_count(), cpu_ms() - t0, q.polygons[0].holes.size());
  }
  std::printf("\n");
}

int main(int argc, char** argv) {
  // --only N: just the deconstruction of the N-vertex star (for profiling).
  int only = 0;
  bool former_only = false;
  bool striped_only = false;
  bool validation_only = false;
  bool cli_only = false;
  std::string baseline_cli;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--only" && i + 1 < argc) only = std::atoi(argv[++i]);
    if (a == "--former-offsets") former_only = true;
    if (a == "--striped-offsets") striped_only = true;
    if (a == "--validation") validation_only = true;
    if (a == "--baseline-cli" && i + 1 < argc) baseline_cli = argv[++i];
    if (a == "--cli") cli_only = true;
  }
  if (cli_only) {
    cli_stages();
    return cli_row(baseline_cli) ? 0 : 1;
  }
  if (only > 0) {
    const penshape::PolygonSet q = wavy_star(only);
    const penshape::Rational r(2080 / 30);
    double c0 = cpu_ms();
    penshape::validate_region(q);
    std::printf("validation alone: cpu %.1f ms\n", cpu_ms() - c0);
    using penshape::fast::OffsetMode;
    std::vector<OffsetMode> modes{OffsetMode::kFormer, OffsetMode::kStriped};
    if (former_only) modes = {OffsetMode::kFormer};
    if (striped_only) modes = {OffsetMode::kStriped};
    for (int round = 0; round < (modes.size() == 1 ? 1 : 3); ++round) {
      for (const OffsetMode mode : modes) {
        penshape::fast::set_offset_mode(mode);
        c0 = cpu_ms();
        const auto t0 = std::chrono::steady_clock::now();
        const penshape::DeconstructResult res = penshape::deconstruct(q, {r, r / 2, r / 16});
        std::printf("%d vertices, %-15s: %s in %.1f ms, cpu %.1f ms (%llu exact fallbacks)\n", only,
                    mode == OffsetMode::kFormer ? "former offsets" : "striped offsets",
                    penshape::to_string(res.answer), ms_since(t0), cpu_ms() - c0,
                    static_cast<unsigned long long>(penshape::fast::exact_fallbacks()));
      }
    }
    return 0;
  }
  validation_table();
  if (validation_only) return 0;
  std::printf(
      "wavy star, r = w/30, eps = r/2, delta = eps/8 (fast engine, no simplification);\n"
      "target at 200k: thread CPU <= 0.7 s (issue 26);\n"
      "deconstruct: wall ms / thread CPU ms (the target is checked on CPU time: the\n"
      "shared machine's load inflates wall time); former offsets: the same call with\n"
      "OffsetMode::kFormer just before, in this process\n");
  std::printf("%8s | %13s | %9s %17s %7s | %23s | %10s %9s\n", "vertices", "validation ms",
              "answer", "deconstruct ms", "target", "former offsets ms", "verify ms", "verdict");
  bool ok = true;
  for (const int n : {10'000, 50'000, 200'000}) {
    const penshape::PolygonSet q = wavy_star(n);
    auto t0 = std::chrono::steady_clock::now();
    penshape::validate_region(q);
    const double validation = ms_since(t0);
    const penshape::Rational r(2080 / 30);
    const penshape::DeconstructParams params{r, r / 2, r / 16};
    // The former offsets first (same process, same input), then the default striped ones.
    penshape::fast::set_offset_mode(penshape::fast::OffsetMode::kFormer);
    double c0 = cpu_ms();
    t0 = std::chrono::steady_clock::now();
    const penshape::Answer former_answer = penshape::deconstruct(q, params).answer;
    const double former = ms_since(t0);
    const double former_cpu = cpu_ms() - c0;
    penshape::fast::set_offset_mode(penshape::fast::OffsetMode::kStriped);
    c0 = cpu_ms();
    t0 = std::chrono::steady_clock::now();
    const penshape::DeconstructResult res = penshape::deconstruct(q, params);
    const double decision = ms_since(t0);
    const double decision_cpu = cpu_ms() - c0;
    t0 = std::chrono::steady_clock::now();
    const penshape::VerifyReport rep = penshape::verify_deconstruction(
        q, {res.answer, r, r / 2, r / 16, res.solution, res.no_witness});
    const double check = ms_since(t0);
    std::printf("%8d | %13.1f | %9s %8.1f/%8.1f %7s | %8.1f/%8.1f (%5s) | %10.1f %9s\n", n,
                validation, penshape::to_string(res.answer), decision, decision_cpu,
                n == 200'000 ? (decision_cpu <= kTargetMs ? "ok" : "FAIL") : "", former, former_cpu,
                penshape::to_string(former_answer), check, penshape::to_string(rep.status));
    if (n == 200'000) ok = ok && decision_cpu <= kTargetMs;
  }
  cli_stages();
  ok = cli_row(baseline_cli) && ok;
  return ok ? 0 : 1;
}
