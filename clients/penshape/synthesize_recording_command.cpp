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
#include "penshape/core/bounding_box.hpp"
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

// The options beyond the paths, checked.
struct Synthesis {
  double mm_per_unit = 0.2;
  double rate = 200;
  std::size_t columns = 3;
  drivers::DeviceIdentity identity;
};

Synthesis read_synthesis(const ParsedArgs& parsed) {
  Synthesis out;
  out.mm_per_unit = parsed.number("--mm-per-unit").value_or(0.2);
  out.rate = parsed.number("--rate").value_or(200);
  const double columns = parsed.number("--columns").value_or(3);
  if (out.mm_per_unit <= 0 || out.rate < 10 || out.rate > 2000 || columns < 1 || columns > 50) {
    throw UsageError("--mm-per-unit must be > 0, --rate in [10, 2000], --columns in [1, 50]");
  }
  out.columns = static_cast<std::size_t>(columns);
  out.identity.bus = Bus::kUsb;
  out.identity.vendor_id = hex_option(parsed, "--vid");
  out.identity.product_id = hex_option(parsed, "--pid");
  out.identity.name = parsed.value("--name").value_or("penshape synthesized tablet");
  return out;
}

// The tablet the reports are for: its descriptor, its pen and its size.
struct Tablet {
  std::vector<std::uint8_t> descriptor;
  drivers::DeviceProfile profile;
  double x_resolution = 0, y_resolution = 0; // units per mm
  double width_mm = 0, height_mm = 0;
  [[nodiscard]] const drivers::PenLayout& pen() const { return profile.decoder.layouts().front(); }
};

// The device's profile, as the drivers build it: the descriptor's pen, or the vendor protocol's
// layout (with the tablet table's size) for tablets known by VID/PID.
Tablet read_tablet(const std::string& descriptor_path, const drivers::DeviceIdentity& identity) {
  Tablet t;
  t.descriptor = drivers::load_recording_file(descriptor_path).descriptor;
  t.profile = drivers::build_profile(identity, t.descriptor);
  if (!t.profile.has_pen()) throw InputError(descriptor_path + ": the descriptor declares no pen");
  t.x_resolution = t.profile.info.x_resolution;
  t.y_resolution = t.profile.info.y_resolution;
  if (t.x_resolution <= 0 || t.y_resolution <= 0) {
    throw InputError(descriptor_path + ": the pen has no physical size (resolution unknown)");
  }
  t.width_mm = t.pen().x_max() / t.x_resolution;
  t.height_mm = t.pen().y_max() / t.y_resolution;
  return t;
}

std::vector<Placed> read_strokes(const std::vector<std::string>& paths) {
  std::vector<Placed> strokes;
  for (const auto& file : collect_stroke_files(paths)) {
    for (auto& s : read_stroke_file(file)) {
      if (s.points.empty()) continue;
      strokes.push_back({std::move(s.points), s.name.empty() ? file : file + " (" + s.name + ")"});
    }
  }
  if (strokes.empty()) throw InputError("no strokes in the given files");
  return strokes;
}

// Plays strokes as the tablet's reports, one after another on one clock.
class ReportPlayer {
 public:
  ReportPlayer(const Tablet& tablet, double rate, drivers::Recording& rec)
      : tablet_(tablet), rate_(rate), rec_(rec) {}

  // The stroke (its box `box`) centred on `center` (mm) and scaled by `scale` mm per its unit:
  // hovering in,
  // resampled at the rate with a pressure ramp, lifting, then 300 ms out of range.
  void play(const std::vector<StrokePoint>& pts, const BoxD& box, PointD center, double scale) {
    mid_ = {0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1)};
    center_ = center;
    scale_ = scale;
    PenSample s;
    s.in_range = true;
    place(pts.front().x, pts.front().y, s);
    for (int h = 0; h < 5; ++h) emit(s); // hovering in
    draw(pts, s);
    s.tip = false;
    s.pressure = 0;
    for (int h = 0; h < 5; ++h) emit(s); // lifting, still in range
    s.in_range = false;
    emit(s);
    clock_us_ += 300000; // out of range between strokes
  }
  [[nodiscard]] std::int64_t clock_us() const { return clock_us_; }

 private:
  void draw(const std::vector<StrokePoint>& pts, PenSample& s) {
    const double t0 = pts.front().t;
    const double duration = std::max(pts.back().t - t0, 1.0 / rate_);
    const auto steps = static_cast<std::size_t>(std::ceil(duration * rate_));
    std::size_t seg = 0;
    for (std::size_t i = 0; i <= steps; ++i) {
      const double t = t0 + duration * static_cast<double>(i) / static_cast<double>(steps);
      while (seg + 1 < pts.size() && pts[seg + 1].t < t) ++seg;
      const auto& a = pts[seg];
      const auto& b = pts[std::min(seg + 1, pts.size() - 1)];
      const double u = b.t > a.t ? std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0) : 0.0;
      place(a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), s);
      // Pressure rises over the first 10% of the stroke and falls over the last 10%.
      const double f = static_cast<double>(i) / static_cast<double>(steps);
      const double ramp = std::clamp(std::min(f, 1.0 - f) * 10.0, 0.2, 1.0);
      s.pressure =
          static_cast<std::uint32_t>(std::lround(0.6 * ramp * tablet_.pen().pressure_max()));
      s.tip = true;
      emit(s);
    }
  }
  void place(double x, double y, PenSample& s) const {
    s.x = static_cast<std::int32_t>(
        std::lround((center_.x + (x - mid_.x) * scale_) * tablet_.x_resolution));
    s.y = static_cast<std::int32_t>(
        std::lround((center_.y + (y - mid_.y) * scale_) * tablet_.y_resolution));
  }
  void emit(const PenSample& s) {
    rec_.events.push_back({clock_us_, drivers::encode_pen_report(tablet_.pen(), s)});
    clock_us_ += static_cast<std::int64_t>(std::llround(1e6 / rate_));
  }

  const Tablet& tablet_;
  double rate_;
  drivers::Recording& rec_;
  std::int64_t clock_us_ = 0;
  PointD mid_, center_;
  double scale_ = 1;
};

// Each stroke centred in its own cell of a grid of `columns` on the tablet; returns the file's
// header comments naming the sources.
std::string play_strokes(const std::vector<Placed>& strokes, const Tablet& tablet,
                         const Synthesis& how, ReportPlayer& player) {
  const std::size_t rows = (strokes.size() + how.columns - 1) / how.columns;
  const double cell_w = tablet.width_mm / static_cast<double>(how.columns);
  const double cell_h = tablet.height_mm / static_cast<double>(rows);
  std::string comments =
      "# Synthesized by `penshape synthesize-recording`: real strokes replayed as this tablet's\n"
      "# reports (" +
      std::to_string(static_cast<int>(how.rate)) + " Hz, linear resampling, synthetic pressure).\n";
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    const auto& pts = strokes[k].points;
    const BoxD box = bounding_box(pts);
    const std::size_t column = k % how.columns;
    const std::size_t row = k / how.columns; // whole rows of the grid above
    const PointD center{cell_w * (static_cast<double>(column) + 0.5),
                        cell_h * (static_cast<double>(row) + 0.5)};
    const double scale = std::min({how.mm_per_unit, 0.9 * cell_w / std::max(box.x1 - box.x0, 1e-9),
                                   0.9 * cell_h / std::max(box.y1 - box.y0, 1e-9)});
    comments += "# stroke " + std::to_string(k) + ": " + strokes[k].source + "\n";
    player.play(pts, box, center, scale);
  }
  return comments;
}

int report_error(const char* what) {
  std::fprintf(stderr, "penshape synthesize-recording: %s\n", what);
  return kExitBadInput;
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
  const Synthesis how = read_synthesis(parsed);
  try {
    const Tablet tablet = read_tablet(*descriptor_path, how.identity);
    const std::vector<Placed> strokes = read_strokes(parsed.positionals());
    drivers::Recording rec;
    rec.identity = how.identity;
    rec.has_identity = true;
    rec.descriptor = tablet.descriptor;
    ReportPlayer player(tablet, how.rate, rec);
    const std::string comments = play_strokes(strokes, tablet, how, player);
    std::ofstream out(*out_path, std::ios::binary);
    if (!out) throw InputError("cannot write '" + *out_path + "'");
    out << comments << drivers::write_hid_recorder(rec);
    if (!out) throw InputError("cannot write '" + *out_path + "'");
    std::printf("%zu strokes, %zu reports, %.1f s -> %s\n", strokes.size(), rec.events.size(),
                static_cast<double>(player.clock_us()) / 1e6, out_path->c_str());
  } catch (const InputError& e) {
    return report_error(e.what());
  } catch (const StrokeFileError& e) {
    return report_error(e.what());
  } catch (const drivers::RecordingError& e) {
    return report_error(
        (*descriptor_path + ": byte " + std::to_string(e.offset()) + ": " + e.what()).c_str());
  } catch (const drivers::DescriptorError& e) {
    return report_error((*descriptor_path + ": " + e.what()).c_str());
  }
  return kExitOk;
}

} // namespace penshape::cli
