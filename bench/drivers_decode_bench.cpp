// Decode throughput and per-report latency of the drivers' hot path on real reports, each
// case beside its baseline (a hand-written decoder of the same report format with fixed
// offsets: the floor a generic layout-driven decoder is measured against).
//
//   drivers_decode_bench [--json] [--seconds S]
//
// Cases: HS610 firmware-mode reports (generic HID layout), HS610 vendor-mode reports
// (UC-Logic layout with split coordinates), and the whole pipeline (decode + sanity check +
// segmentation). Target: >= 1 M reports/s.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_data.hpp"
#include "bench_support.hpp"
#include "penshape/drivers/pen_pipeline.hpp"
#include "penshape/drivers/recording.hpp"

namespace {

using namespace penshape;
using namespace penshape::drivers;
using Clock = std::chrono::steady_clock;

std::filesystem::path hid_dir() {
  std::filesystem::path dir = std::filesystem::path(penshape::bench::shared_data_dir()) / "hid";
  penshape::bench::say_data("drivers_decode_bench", dir.string() + " (real tablet data)");
  return dir;
}

std::vector<std::vector<std::uint8_t>> reports_of(const std::string& rel) {
  const auto dump = read_usbhid_dump(read_file(hid_dir() / rel));
  std::vector<std::vector<std::uint8_t>> out;
  for (const auto& [iface, events] : dump.streams) {
    for (const auto& e : events) out.push_back(e.bytes);
  }
  return out;
}

volatile std::uint64_t g_sink = 0; // keeps results alive

struct Result {
  std::string name;
  double reports_per_s = 0;
  double mean_ns = 0;
  double p50_ns = 0; // median per-report time over batches (robust to preemption on a busy box)
  double p99_ns = 0; // 99th percentile of the per-report time of batches of 1024 reports
};

template <typename F>
Result measure(const std::string& name, const std::vector<std::vector<std::uint8_t>>& reports,
               double seconds, F&& decode_one) {
  // Batches amortise the clock read (slow on some VMs) over many reports.
  constexpr std::size_t kBatch = 1024;
  std::vector<double> batch_ns;
  std::uint64_t done = 0;
  std::uint64_t acc = 0;
  const auto start = Clock::now();
  const auto until = start + std::chrono::duration<double>(seconds);
  std::size_t i = 0;
  auto b0 = start;
  for (;;) {
    for (std::size_t k = 0; k < kBatch; ++k) {
      acc += decode_one(reports[i], static_cast<std::int64_t>(done + k));
      if (++i == reports.size()) i = 0;
    }
    const auto b1 = Clock::now();
    batch_ns.push_back(std::chrono::duration<double, std::nano>(b1 - b0).count() / kBatch);
    done += kBatch;
    b0 = b1;
    if (b1 >= until) break;
  }
  const double total = std::chrono::duration<double>(b0 - start).count();
  g_sink = g_sink + acc;
  std::sort(batch_ns.begin(), batch_ns.end());
  Result r;
  r.name = name;
  r.reports_per_s = static_cast<double>(done) / total;
  r.mean_ns = total * 1e9 / static_cast<double>(done);
  r.p99_ns = batch_ns[batch_ns.size() * 99 / 100];
  r.p50_ns = batch_ns[batch_ns.size() / 2];
  return r;
}

std::uint32_t le16(const std::vector<std::uint8_t>& r, std::size_t at) {
  return static_cast<std::uint32_t>(r[at] | (r[at + 1] << 8));
}

// A tilt byte read as two's complement.
std::int16_t signed_byte(std::uint8_t b) {
  return static_cast<std::int16_t>(b >= 0x80 ? b - 0x100 : b);
}

} // namespace

int main(int argc, char** argv) {
  const auto args = penshape::bench::parse_seconds_args(argc, argv, "drivers_decode_bench", 0.5);
  if (!args) return 2;
  const bool json = args->json;
  const double seconds = args->seconds;
  const auto firmware = reports_of("digimend-tablets/Huion_HS610/dumps/default/pen_tilt.txt");
  const auto vendor = reports_of("digimend-tablets/Huion_HS610/dumps/enabled/pen_tilt.txt");
  const auto desc =
      read_usbhid_dump(read_file(hid_dir() / "digimend-tablets/Huion_HS610/rd/original1.txt"))
          .descriptors.begin()
          ->second;
  const DeviceIdentity id{Bus::kUsb, 0x256c, 0x006d, "HS610"};
  const DeviceProfile fw = build_profile(id, desc);
  const std::vector<std::uint8_t> s200 = {0x13, 0x03, 0x70, 0xC6, 0x00, 0x06, 0x7C,
                                          0x00, 0xFF, 0x1F, 0xD8, 0x13, 0x03};
  const DeviceProfile vend = build_profile(id, {}, {{200, s200}});

  std::vector<Result> results;
  PenSample s;
  results.push_back(measure("firmware HID layout: PenDecoder", firmware, seconds,
                            [&](const auto& r, std::int64_t t) {
                              fw.decoder.decode(r, t, s);
                              return static_cast<std::uint64_t>(std::int64_t{s.x} + s.pressure);
                            }));
  results.push_back(measure("firmware: baseline fixed offsets", firmware, seconds,
                            [&](const auto& r, std::int64_t t) {
                              if (r.size() < 10 || r[0] != 0x0A) return std::uint64_t{0};
                              s.time_us = t;
                              s.tip = (r[1] & 1) != 0;
                              s.in_range = (r[1] & 0x40) != 0;
                              s.x = static_cast<std::int32_t>(le16(r, 2));
                              s.y = static_cast<std::int32_t>(le16(r, 4));
                              s.pressure = le16(r, 6);
                              s.tilt_x = signed_byte(r[8]);
                              s.tilt_y = signed_byte(r[9]);
                              return static_cast<std::uint64_t>(std::int64_t{s.x} + s.pressure);
                            }));
  results.push_back(measure("vendor UC-Logic v2 layout: PenDecoder", vendor, seconds,
                            [&](const auto& r, std::int64_t t) {
                              vend.decoder.decode(r, t, s);
                              return static_cast<std::uint64_t>(std::int64_t{s.x} + s.pressure);
                            }));
  results.push_back(measure(
      "vendor: baseline fixed offsets", vendor, seconds, [&](const auto& r, std::int64_t t) {
        if (r.size() < 12 || r[0] != 0x08 || (r[1] & 0x60) != 0) {
          return std::uint64_t{0};
        }
        s.time_us = t;
        s.tip = (r[1] & 1) != 0;
        s.in_range = (r[1] & 0x80) != 0;
        s.x = static_cast<std::int32_t>(le16(r, 2) | (std::uint32_t{r[8]} << 16));
        s.y = static_cast<std::int32_t>(le16(r, 4) | (std::uint32_t{r[9]} << 16));
        s.pressure = le16(r, 6);
        s.tilt_x = signed_byte(r[10]);
        s.tilt_y = signed_byte(r[11]);
        return static_cast<std::uint64_t>(std::int64_t{s.x} + s.pressure);
      }));
  std::uint64_t strokes = 0;
  PenPipeline pipeline(vend, {}, {.on_sample = {}, .on_stroke = [&](Stroke&&) { ++strokes; }});
  results.push_back(measure("vendor: full pipeline (decode+segment)", vendor, seconds,
                            [&](const auto& r, std::int64_t t) {
                              pipeline.on_report(r, t * 4000);
                              return strokes;
                            }));

  if (json) {
    for (const auto& r : results) {
      std::printf(
          "{\"case\":\"%s\",\"reports_per_s\":%.0f,\"mean_ns\":%.2f,\"p50_ns\":%.2f,"
          "\"p99_ns\":%.2f}\n",
          r.name.c_str(), r.reports_per_s, r.mean_ns, r.p50_ns, r.p99_ns);
    }
    return 0;
  }
  std::printf("%-42s %14s %9s %9s %9s\n", "case", "reports/s", "mean ns", "p50 ns", "p99 ns");
  for (const auto& r : results) {
    std::printf("%-42s %14.0f %9.1f %9.1f %9.1f\n", r.name.c_str(), r.reports_per_s, r.mean_ns,
                r.p50_ns, r.p99_ns);
  }
  std::printf("target: >= 1000000 reports/s (a 1 kHz tablet then costs < 0.1%% of a core)\n");
  return 0;
}
