// Decode throughput of every report family (drivers/data/families.tsv), one row each, beside a
// baseline: a hand-written reader that only loads the X, Y and pressure words at the family's
// fixed byte positions (the floor a layout-driven decoder is measured against). Reports are a
// pen stroke (a circle with pressure and tilt, tip down and hovering) written by the pen-report
// encoder into each family's layout, plus one report in 16 of another kind or the wrong length,
// so the match and junk paths are timed too. Needs no data files. Target: >= 1 M reports/s.
//
//   family_decode_bench [--json] [--seconds S]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "penshape/drivers/pen_decoder.hpp"
#include "penshape/drivers/pen_encoder.hpp"
#include "penshape/drivers/report_families.hpp"

namespace {

using namespace penshape;
using namespace penshape::drivers;
using Clock = std::chrono::steady_clock;
using Reports = std::vector<std::vector<std::uint8_t>>;

volatile std::uint64_t g_sink = 0; // keeps results alive

// Reports per second of `decode_one` over the reports, cycled for `seconds`.
template <typename F>
double rate(const Reports& reports, double seconds, F&& decode_one) {
  constexpr std::size_t kBatch = 4096;
  std::uint64_t done = 0, acc = 0;
  std::size_t i = 0;
  const auto start = Clock::now();
  const auto until = start + std::chrono::duration<double>(seconds);
  auto now = start;
  while (now < until) {
    for (std::size_t k = 0; k < kBatch; ++k) {
      acc += decode_one(reports[i]);
      if (++i == reports.size()) i = 0;
    }
    done += kBatch;
    now = Clock::now();
  }
  g_sink = g_sink + acc;
  return static_cast<double>(done) / std::chrono::duration<double>(now - start).count();
}

// A stroke of 1,000 samples through the layout, every 16th report replaced by a pad-like frame
// (the match byte flipped) or a report one byte short.
Reports stroke_reports(const PenLayout& l, const TabletSpec& spec) {
  Reports out;
  for (int i = 0; i < 1000; ++i) {
    const double a = i * 0.0063;
    PenSample s;
    s.x = static_cast<std::int32_t>(spec.x_max * (0.5 + 0.4 * std::cos(a)));
    s.y = static_cast<std::int32_t>(spec.y_max * (0.5 + 0.4 * std::sin(a)));
    s.tip = i % 200 < 180;
    s.in_range = true;
    s.pressure = s.tip ? static_cast<std::uint32_t>(500 + i % 3000) : 0U;
    s.tilt_x = static_cast<std::int16_t>(i % 60 - 30);
    s.tilt_y = static_cast<std::int16_t>(30 - i % 60);
    auto r = encode_pen_report(l, s);
    if (i % 32 == 7 && l.match_mask != 0 && l.match_byte < r.size())
      r[l.match_byte] ^= l.match_mask;
    if (i % 32 == 23) r.pop_back();
    out.push_back(std::move(r));
  }
  return out;
}

std::uint32_t word(const std::vector<std::uint8_t>& r, std::uint32_t bit_offset) {
  const std::size_t at = bit_offset / 8;
  return at + 1 < r.size() ? static_cast<std::uint32_t>(r[at] | (r[at + 1] << 8)) : 0U;
}

} // namespace

int main(int argc, char** argv) {
  const auto args = penshape::bench::parse_seconds_args(argc, argv, "family_decode_bench", 0.2);
  if (!args) return 2;
  const bool json = args->json;
  const double seconds = args->seconds;
  TabletSpec spec;
  spec.x_max = 50800;
  spec.y_max = 31750;
  spec.pressure_max = 8191;
  spec.x_resolution = spec.y_resolution = 200;
  if (!json) {
    std::printf("%-24s %7s %12s %9s %14s %7s\n", "family", "layouts", "decode M/s", "ns/report",
                "baseline M/s", ">=1M/s");
  }
  int failed = 0;
  for (const auto& f : builtin_families()) {
    const auto layouts = family_layouts(f, spec);
    if (layouts.empty()) continue; // descriptor families: timed by drivers_decode_bench
    const Reports reports = stroke_reports(layouts.front(), spec);
    const PenDecoder decoder(layouts);
    PenSample s;
    const double decoded = rate(reports, seconds, [&](const std::vector<std::uint8_t>& r) {
      return decoder.decode(r, 0, s) == DecodeStatus::kPen
                 ? static_cast<std::uint64_t>(s.x + s.y) + s.pressure
                 : 0U;
    });
    const PenLayout& l = layouts.front();
    const double baseline = rate(reports, seconds, [&](const std::vector<std::uint8_t>& r) {
      return static_cast<std::uint64_t>(word(r, l.x.bit_offset)) + word(r, l.y.bit_offset) +
             word(r, l.pressure.bit_offset);
    });
    const bool ok = decoded >= 1e6;
    failed += ok ? 0 : 1;
    if (json) {
      std::printf(
          "{\"family\":\"%s\",\"layouts\":%zu,\"reports_per_s\":%.0f,\"ns_per_report\":"
          "%.1f,\"baseline_reports_per_s\":%.0f,\"meets_target\":%s}\n",
          f.name.c_str(), layouts.size(), decoded, 1e9 / decoded, baseline, ok ? "true" : "false");
    } else {
      std::printf("%-24s %7zu %12.1f %9.1f %14.1f %7s\n", f.name.c_str(), layouts.size(),
                  decoded / 1e6, 1e9 / decoded, baseline / 1e6, ok ? "yes" : "NO");
    }
  }
  return failed == 0 ? 0 : 1;
}
