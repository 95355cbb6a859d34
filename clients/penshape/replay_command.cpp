// `penshape replay FILE [--json]`: decodes a recorded report stream (hid-recorder or
// usbhid-dump) through the same decoder and segmenter as a live device and prints the samples
// and strokes; with penshaped running (and without --local), each stroke's shape as the daemon
// certifies it.
#include "replay_command.hpp"

#include <cstdio>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "daemon_channel.hpp"
#include "device_args.hpp"
#include "json_writer.hpp"
#include "live_event_text.hpp"
#include "penshape/drivers/replay.hpp"
#include "replay_daemon.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape replay FILE [--json] [--vid HEX --pid HEX] [--descriptor FILE]\n"
    "                       [--original-speed] [--local | --socket PATH | --address ADDR]\n\n"
    "Replays FILE (hid-recorder, or a usbhid-dump stream: its busiest interface) through the\n"
    "live decode path and prints every pen sample and every stroke. When penshaped answers (at\n"
    "--socket/--address, else its default socket) each stroke is also submitted to it and the\n"
    "shape it certifies is printed after the stroke; otherwise, or with --local, the replay is\n"
    "local only. Which of the two ran is said on stderr. --vid/--pid choose the\n"
    "tablet (protocol, maxima) when the file has no I: line; --descriptor gives the report\n"
    "descriptor (raw, hex or hid-recorder file) when it has none. --original-speed waits between\n"
    "reports as recorded (default: as fast as possible, same result).\n\n"
    "--json prints one object per line: a sample {\"t\", \"x\", \"y\", \"pressure\", \"tilt_x\",\n"
    "\"tilt_y\", \"tip\", \"in_range\", \"buttons\"} (t in seconds from the first report, x/y in\n"
    "device units), and after each stroke's last sample {\"stroke\", \"t_start\", \"t_end\",\n"
    "\"samples\"}, and through penshaped {\"stroke\", \"shape\": {...}} (keys as in penshape "
    "watch).\n"
    "Report counts, the report family and the physical size (and whether it came from the\n"
    "tablet table, the descriptor or a vendor probe) go to stderr. Exit 2 on a malformed file,\n"
    "naming the byte offset.";

double seconds(std::int64_t us) { return static_cast<double>(us) / 1e6; }

// penshaped at the options' address unless --local; says on stderr which way the replay runs.
std::optional<ReplayDaemon> connect_unless_local(const ParsedArgs& parsed) {
  if (parsed.flag("--local")) {
    std::fputs("penshape replay: local (--local): decoded here, no shapes\n", stderr);
    return std::nullopt;
  }
  const std::string address = daemon_address(parsed);
  std::string why;
  auto daemon = ReplayDaemon::connect(address, why);
  if (daemon) {
    std::fprintf(stderr, "penshape replay: through penshaped at %s: shapes certified by it\n",
                 address.c_str());
  } else {
    std::fprintf(stderr, "penshape replay: local: penshaped does not answer at %s, no shapes\n",
                 address.c_str());
  }
  return daemon;
}

void print_daemon_shape(ReplayDaemon& daemon, const Stroke& stroke, const TabletInfo& tablet,
                        bool json) {
  const v1::Shape shape = daemon.recognize(stroke, tablet);
  if (json) {
    JsonWriter w;
    w.begin_object().key("stroke").integer(static_cast<std::int64_t>(stroke.id)).key("shape");
    write_shape_json(w, shape);
    w.end_object();
    std::puts(w.str().c_str());
  } else {
    std::printf("  shape: %s\n", shape_summary(shape).c_str());
  }
}

// "size 254.0 x 158.8 mm from the table", or a warning that there is none.
std::string size_text(const drivers::ReplayResult& r) {
  if (r.size_source == drivers::SizeSource::kUnknown) {
    return "physical size unknown (coordinates are device units, not millimetres)";
  }
  char buf[96];
  std::snprintf(buf, sizeof buf, "size %.1f x %.1f mm from the %s", r.tablet.width_mm(),
                r.tablet.height_mm(),
                std::string(drivers::size_source_name(r.size_source)).c_str());
  return buf;
}

// The recording replayed through the drivers (no daemon); nothing on a file the drivers refuse
// (the error printed).
std::optional<drivers::ReplayResult> replay_file(const ParsedArgs& parsed) {
  try {
    const drivers::Recording rec = load_device_file(parsed);
    if (rec.events.empty()) throw drivers::RecordingError(0, "the file holds no reports");
    return drivers::replay(rec, parsed.flag("--original-speed")
                                    ? drivers::ReplaySpeed::kOriginal
                                    : drivers::ReplaySpeed::kAsFastAsPossible);
  } catch (const drivers::RecordingError& e) {
    std::fprintf(stderr, "penshape replay: %s: %s\n", device_file_name(parsed).c_str(), e.what());
  } catch (const drivers::DescriptorError& e) {
    std::fprintf(stderr, "penshape replay: %s: %s\n", device_file_name(parsed).c_str(), e.what());
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "penshape replay: %s: %s\n", device_file_name(parsed).c_str(), e.what());
  }
  return std::nullopt;
}

void print_header(const drivers::ReplayResult& result, bool json) {
  const std::string size = size_text(result);
  if (!json) {
    std::printf(
        "# %s: x_max %d y_max %d pressure_max %u\n# family %s (layout %s), %s\n"
        "# %10s %7s %7s %6s %5s %5s %3s %3s %4s\n",
        result.tablet.name.c_str(), result.tablet.x_max, result.tablet.y_max,
        result.tablet.pressure_max, result.family.c_str(), result.layout.c_str(), size.c_str(), "t",
        "x", "y", "press", "tiltx", "tilty", "tip", "rng", "btns");
  }
  std::fprintf(stderr, "penshape replay: family %s (layout %s), %s\n", result.family.c_str(),
               result.layout.c_str(), size.c_str());
}

void print_sample(const PenSample& p, bool json) {
  if (!json) {
    std::printf("  %10.6f %7d %7d %6u %5d %5d %3d %3d %4u\n", seconds(p.time_us), p.x, p.y,
                p.pressure, p.tilt_x, p.tilt_y, p.tip ? 1 : 0, p.in_range ? 1 : 0, p.buttons);
    return;
  }
  JsonWriter w;
  w.begin_object()
      .key("t")
      .number(seconds(p.time_us))
      .key("x")
      .integer(p.x)
      .key("y")
      .integer(p.y)
      .key("pressure")
      .integer(p.pressure)
      .key("tilt_x")
      .integer(p.tilt_x)
      .key("tilt_y")
      .integer(p.tilt_y)
      .key("tip")
      .boolean(p.tip)
      .key("in_range")
      .boolean(p.in_range)
      .key("buttons")
      .integer(p.buttons)
      .end_object();
  std::puts(w.str().c_str());
}

void print_stroke(const Stroke& s, bool json) {
  if (!json) {
    std::printf("stroke %llu: %zu samples, %.6f .. %.6f s\n", static_cast<unsigned long long>(s.id),
                s.samples.size(), seconds(s.samples.front().time_us),
                seconds(s.samples.back().time_us));
    return;
  }
  JsonWriter w;
  w.begin_object()
      .key("stroke")
      .integer(static_cast<std::int64_t>(s.id))
      .key("t_start")
      .number(seconds(s.samples.front().time_us))
      .key("t_end")
      .number(seconds(s.samples.back().time_us))
      .key("samples")
      .integer(static_cast<std::int64_t>(s.samples.size()))
      .end_object();
  std::puts(w.str().c_str());
}

void print_counters(const drivers::ReplayResult& result) {
  const auto& c = result.counters;
  std::fprintf(stderr,
               "penshape replay: %llu reports: %llu pen samples, %llu other, %llu junk, %llu out "
               "of range; %zu strokes\n",
               static_cast<unsigned long long>(c.reports),
               static_cast<unsigned long long>(c.pen_samples),
               static_cast<unsigned long long>(c.other_reports),
               static_cast<unsigned long long>(c.junk_reports),
               static_cast<unsigned long long>(c.out_of_range), result.strokes.size());
  if (c.reports > 0 && c.pen_samples == 0) {
    std::fprintf(stderr,
                 "penshape replay: no report matched the pen layout (firmware-mode stream? give "
                 "--descriptor)\n");
  }
}

// Samples and strokes interleaved in time: a stroke is printed (with the daemon's shape, when
// connected) once its last sample is out.
void print_replay(const drivers::ReplayResult& result, std::optional<ReplayDaemon>& daemon,
                  bool json) {
  std::size_t next_stroke = 0;
  const auto stroke_out = [&](const Stroke& s) {
    print_stroke(s, json);
    if (daemon) print_daemon_shape(*daemon, s, result.tablet, json);
  };
  for (std::size_t i = 0; i < result.samples.size(); ++i) {
    const PenSample& p = result.samples[i];
    print_sample(p, json);
    while (next_stroke < result.strokes.size() &&
           result.strokes[next_stroke].samples.back().time_us <= p.time_us &&
           (i + 1 == result.samples.size() ||
            result.samples[i + 1].time_us > result.strokes[next_stroke].samples.back().time_us)) {
      stroke_out(result.strokes[next_stroke++]);
    }
  }
  while (next_stroke < result.strokes.size()) stroke_out(result.strokes[next_stroke++]);
}

} // namespace

int run_replay(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, live_arg_spec({.flags = {"--json", "--local", "--original-speed"},
                                               .options = {"--vid", "--pid", "--descriptor"}}));
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  if (parsed.flag("--local") && (parsed.value("--socket") || parsed.value("--address"))) {
    throw UsageError("--local replays without penshaped: it takes no --socket or --address");
  }
  const std::optional<drivers::ReplayResult> result = replay_file(parsed);
  if (!result) return kExitBadInput;
  if (result->tablet.x_max == 0) {
    std::fprintf(stderr,
                 "penshape replay: %s: no pen report layout (give the descriptor in the file, or "
                 "--vid/--pid of a known tablet)\n",
                 device_file_name(parsed).c_str());
    return kExitBadInput;
  }
  std::optional<ReplayDaemon> daemon = connect_unless_local(parsed);
  const bool json = parsed.flag("--json");
  print_header(*result, json);
  print_replay(*result, daemon, json);
  print_counters(*result);
  return kExitOk;
}

} // namespace penshape::cli
