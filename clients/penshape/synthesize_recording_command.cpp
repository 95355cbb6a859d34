// `penshape synthesize-recording`: real pen strokes (e.g. the $1 gesture logs) replayed as the
// input reports of a real tablet's descriptor, written as a hid-recorder file — how the bundled
// recordings/ were made, and a way to make more.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "geometry_cli.hpp"
#include "penshape/drivers/device_profile.hpp"
#include "penshape/drivers/hid_descriptor.hpp"
#include "penshape/drivers/pen_encoder.hpp"
#include "penshape/drivers/pen_layout.hpp"
#include "penshape/drivers/recording.hpp"
#include "stroke_files.hpp"
#include "synthesize_recording_command.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape synthesize-recording --descriptor FILE --vid HEX --pid HEX --out FILE\n"
    "           [--name NAME] [--mm-per-unit S] [--rate HZ] [--columns N] STROKES...\n\n"
    "Writes the strokes in STROKES (files or directories: $1 gesture-log .xml or .jsonl, see\n"
    "`penshape recognize --help`) as a hid-recorder recording of the tablet whose report\n"
    "descriptor is in FILE (raw bytes or a hid-recorder file): each stroke is scaled by S\n"
    "millimetres per input unit (default 0.2), placed in a grid of N columns (default 3) on the\n"
    "tablet, resampled to HZ reports per second (default 200) by linear interpolation, with a\n"
    "smooth pressure profile, hover reports before and after, and 300 ms out of range between\n"
    "strokes. The file's header comments name the sources. Exit codes: 0 ok, 2 bad input.";

struct Placed {
  std::vector<StrokePoint> points; // in tablet millimetres, time in seconds from stroke start
  std::string source;
};

std::uint16_t hex_option(const ParsedArgs& parsed, const char* name) {
  const auto text = parsed.value(name);
  if (!text) throw UsageError(std::string("option '") + name + "' is required");
  std::size_t used = 0;
  unsigned long v = 0;
  try {
    v = std::stoul(*text, &used, 16);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text->size() || v > 0xFFFF) {
    throw UsageError(std::string("option '") + name + "' needs a 16-bit hex number, got '" + *text +
                     "'");
  }
  return static_cast<std::uint16_t>(v);
}

} // namespace

int run_synthesize_recording(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, {.flags = {"--help"},
                                 .options = {"--descriptor", "--vid", "--pid", "--out", "--name",
                                             "--mm-per-unit", "--rate", "--columns"}});
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  const auto descriptor_path = parsed.value("--descriptor");
  const auto out_path = parsed.value("--out");
  if (!descriptor_path || !out_path) throw UsageError("--descriptor and --out are required");
  if (parsed.positionals().empty()) throw UsageError("expected stroke files or directories");
  const double mm_per_unit = parsed.number("--mm-per-unit").value_or(0.2);
  const double rate = parsed.number("--rate").value_or(200);
  const double columns_d = parsed.number("--columns").value_or(3);
  if (mm_per_unit <= 0 || rate < 10 || rate > 2000 || columns_d < 1 || columns_d > 50) {
    throw UsageError("--mm-per-unit must be > 0, --rate in [10, 2000], --columns in [1, 50]");
  }
  const auto columns = static_cast<std::size_t>(columns_d);

  drivers::DeviceIdentity identity;
  identity.bus = Bus::kUsb;
  identity.vendor_id = hex_option(parsed, "--vid");
  identity.product_id = hex_option(parsed, "--pid");
  identity.name = parsed.value("--name").value_or("penshape synthesized tablet");
  try {
    const drivers::Recording source = drivers::load_recording_file(*descriptor_path);
    // The device's profile, as the drivers build it: the descriptor's pen, or the vendor
    // protocol's layout (with the tablet table's size) for tablets known by VID/PID.
    const drivers::DeviceProfile profile = drivers::build_profile(identity, source.descriptor);
    if (!profile.has_pen()) throw InputError(*descriptor_path + ": the descriptor declares no pen");
    const drivers::PenLayout& pen = profile.decoder.layouts().front();
    const double x_resolution = profile.info.x_resolution, y_resolution = profile.info.y_resolution;
    if (x_resolution <= 0 || y_resolution <= 0) {
      throw InputError(*descriptor_path + ": the pen has no physical size (resolution unknown)");
    }
    const double width_mm = pen.x_max() / x_resolution;
    const double height_mm = pen.y_max() / y_resolution;

    std::vector<Placed> strokes;
    for (const auto& file : collect_stroke_files(parsed.positionals())) {
      for (auto& s : read_stroke_file(file)) {
        if (s.points.empty()) continue;
        strokes.push_back(
            {std::move(s.points), s.name.empty() ? file : file + " (" + s.name + ")"});
      }
    }
    if (strokes.empty()) throw InputError("no strokes in the given files");
    // Grid cells on the tablet; each stroke is centred in its own cell.
    const std::size_t rows = (strokes.size() + columns - 1) / columns;
    const double cell_w = width_mm / static_cast<double>(columns);
    const double cell_h = height_mm / static_cast<double>(rows);

    drivers::Recording rec;
    rec.identity = identity;
    rec.has_identity = true;
    rec.descriptor = source.descriptor;
    std::int64_t clock_us = 0;
    std::string header_comments =
        "# Synthesized by `penshape synthesize-recording`: real strokes replayed as this tablet's\n"
        "# reports (" +
        std::to_string(static_cast<int>(rate)) + " Hz, linear resampling, synthetic pressure).\n";
    for (std::size_t k = 0; k < strokes.size(); ++k) {
      auto& pts = strokes[k].points;
      double xmin = pts[0].x, xmax = pts[0].x, ymin = pts[0].y, ymax = pts[0].y;
      for (const auto& p : pts) {
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y);
        ymax = std::max(ymax, p.y);
      }
      const double cx = cell_w * (static_cast<double>(k % columns) + 0.5);
      const double cy = cell_h * (static_cast<double>(k / columns) + 0.5);
      const double scale = std::min({mm_per_unit, 0.9 * cell_w / std::max(xmax - xmin, 1e-9),
                                     0.9 * cell_h / std::max(ymax - ymin, 1e-9)});
      auto to_units = [&](double x, double y, PenSample& s) {
        s.x = static_cast<std::int32_t>(
            std::lround((cx + (x - 0.5 * (xmin + xmax)) * scale) * x_resolution));
        s.y = static_cast<std::int32_t>(
            std::lround((cy + (y - 0.5 * (ymin + ymax)) * scale) * y_resolution));
      };
      header_comments += "# stroke " + std::to_string(k) + ": " + strokes[k].source + "\n";
      const double t0 = pts.front().t;
      const double duration = std::max(pts.back().t - t0, 1.0 / rate);
      const auto steps = static_cast<std::size_t>(std::ceil(duration * rate));
      const auto period_us = static_cast<std::int64_t>(std::llround(1e6 / rate));
      auto emit = [&](const PenSample& s) {
        rec.events.push_back({clock_us, drivers::encode_pen_report(pen, s)});
        clock_us += period_us;
      };
      PenSample s;
      s.in_range = true;
      to_units(pts.front().x, pts.front().y, s);
      for (int h = 0; h < 5; ++h) emit(s); // hovering in
      std::size_t seg = 0;
      for (std::size_t i = 0; i <= steps; ++i) {
        const double t = t0 + duration * static_cast<double>(i) / static_cast<double>(steps);
        while (seg + 1 < pts.size() && pts[seg + 1].t < t) ++seg;
        const auto& a = pts[seg];
        const auto& b = pts[std::min(seg + 1, pts.size() - 1)];
        const double u = b.t > a.t ? std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0) : 0.0;
        to_units(a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), s);
        // Pressure rises over the first 10% of the stroke and falls over the last 10%.
        const double f = static_cast<double>(i) / static_cast<double>(steps);
        const double ramp = std::clamp(std::min(f, 1.0 - f) * 10.0, 0.2, 1.0);
        s.pressure = static_cast<std::uint32_t>(std::lround(0.6 * ramp * pen.pressure_max()));
        s.tip = true;
        emit(s);
      }
      s.tip = false;
      s.pressure = 0;
      for (int h = 0; h < 5; ++h) emit(s); // lifting, still in range
      s.in_range = false;
      emit(s);
      clock_us += 300'000; // out of range between strokes
    }
    std::ofstream out(*out_path, std::ios::binary);
    if (!out) throw InputError("cannot write '" + *out_path + "'");
    out << header_comments << drivers::write_hid_recorder(rec);
    if (!out) throw InputError("cannot write '" + *out_path + "'");
    std::printf("%zu strokes, %zu reports, %.1f s -> %s\n", strokes.size(), rec.events.size(),
                static_cast<double>(clock_us) / 1e6, out_path->c_str());
  } catch (const InputError& e) {
    std::fprintf(stderr, "penshape synthesize-recording: %s\n", e.what());
    return kExitBadInput;
  } catch (const StrokeFileError& e) {
    std::fprintf(stderr, "penshape synthesize-recording: %s\n", e.what());
    return kExitBadInput;
  } catch (const drivers::RecordingError& e) {
    std::fprintf(stderr, "penshape synthesize-recording: %s: byte %zu: %s\n",
                 descriptor_path->c_str(), e.offset(), e.what());
    return kExitBadInput;
  } catch (const drivers::DescriptorError& e) {
    std::fprintf(stderr, "penshape synthesize-recording: %s: %s\n", descriptor_path->c_str(),
                 e.what());
    return kExitBadInput;
  }
  return kExitOk;
}

} // namespace penshape::cli
