// `penshape watch`: what is drawn on the tablets, live: strokes, shapes, optionally samples and
// previews; readable lines or JSON lines, and optionally one SVG picture per stroke.
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include "args.hpp"
#include "cancel_on_signal.hpp"
#include "command.hpp"
#include "daemon_channel.hpp"
#include "device_events.hpp"
#include "live_commands.hpp"
#include "live_event_text.hpp"
#include "penshape/v1/live.grpc.pb.h"
#include "stroke_figure.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape watch [--json] [--samples] [--previews] [--deconstructions] [--devices]\n"
    "                      [--device ID[,ID...]]\n"
    "                      [--count N] [--duration SECONDS] [--svg-dir DIR]\n"
    "                      [--socket PATH | --address ADDR]\n\n"
    "Prints what penshaped sees, as it happens: devices attached and detached, strokes started\n"
    "and finished, the shapes they snap to; until Ctrl-C, --count or --duration. A shape that\n"
    "completes a group of strokes (a rectangle drawn side by side) names the strokes whose ink\n"
    "it replaces and the earlier shapes it supersedes. Hold to snap (config snap_trigger hold or\n"
    "both): a stroke whose pen holds still snaps before pen-up (held), then follows the pen when\n"
    "it moves on (follows the pen) and is final at pen-up (released).\n\n"
    "options:\n"
    "  --json             one JSON object per event: sequence, published_us, device_id, type\n"
    "                     (device_attached, device_detached, stroke_started, samples,\n"
    "                     stroke_finished, preview, shape, deconstructed, dropped) and the\n"
    "                     type's fields (stroke_id; samples; shape {kind, confidence,\n"
    "                     intent (writing | drawing: writing is left as drawn unless\n"
    "                     snap_writing), writing_score,\n"
    "                     vertices | circle | ellipse | arc | arrow {tail, tip, barbs,\n"
    "                     tail_barbs, head_angle_rad, shaft_bulge, shaft_bends[, shaft_end]},\n"
    "                     hausdorff_bound, tolerance,\n"
    "                     pen_radius, method} in mm; a shape event also has shape_id,\n"
    "                     replaced_stroke_ids (strokes whose ink the shape replaces: several\n"
    "                     when it completes a group of strokes), supersedes_shape_ids and\n"
    "                     supersedes_sequences (earlier answers it replaces), tidy and\n"
    "                     trigger (pen_up, hold, follow, release), hold snaps also hold\n"
    "                     {certified_samples, hold_point, pen_point, adjusted, held_shape_id}\n"
    "                     and the shape's certificate its scope (drawn_part, or\n"
    "                     drawn_part+user_edit once dragged); a\n"
    "                     preview may have a group {shape, replaced_stroke_ids,\n"
    "                     supersedes_shape_ids, tidy}; deconstructed {answer, solution_vertices,\n"
    "                     raw_vertices, simplified, hausdorff_bound, tolerance, precision,\n"
    "                     pen_radius, compute_us, not_deconstructed})\n"
    "  --samples          also the raw pen samples (many events per second)\n"
    "  --previews         also the shapes a stroke in progress would snap to\n"
    "  --deconstructions  also each stroke's offset deconstruction: the outline P whose\n"
    "                     pen-radius offset is certified within eps of the ink (after the shape)\n"
    "  --devices          also devices attached (those attached now first) and detached\n"
    "  --device IDS       only these devices (ids from `penshape devices`, comma-separated)\n"
    "  --count N          stop after N events\n"
    "  --duration SECONDS stop after this time\n"
    "  --svg-dir DIR      write DIR/stroke-DEVICE-ID.svg for every finished stroke: samples,\n"
    "                     ink, snapped shape and its tolerance band (DIR is created)\n"
    "%s\n"
    "Status lines go to stderr. Exit codes: 0 ok (also when stopped by Ctrl-C, --count,\n"
    "--duration or the daemon shutting down), 2 bad usage, 1 daemon not running or failed.\n";

// Pictures of finished strokes: a stroke waits for its shape, unless it will get none.
class SvgArchive {
 public:
  explicit SvgArchive(std::filesystem::path dir) : dir_(std::move(dir)) {}

  void on_event(const v1::LiveEvent& event) {
    if (event.has_stroke_finished()) {
      const auto& f = event.stroke_finished();
      if (!f.not_analysed().empty()) {
        write(event.device_id(), f, nullptr);
      } else {
        pending_[{event.device_id(), f.stroke().id()}] = f;
      }
    } else if (event.has_stroke_started()) {
      // A device's shape follows its StrokeFinished at once: a stroke still waiting when that
      // device starts another one gets none (the daemon has no recognizer).
      flush_device(event.device_id());
    } else if (event.has_shape()) {
      const auto it = pending_.find({event.device_id(), event.shape().stroke_id()});
      if (it == pending_.end()) return; // its stroke finished before we subscribed
      write(event.device_id(), it->second, &event.shape().shape());
      pending_.erase(it);
    }
  }

  void flush_device(const std::string& device) {
    for (auto it = pending_.begin(); it != pending_.end();) {
      if (it->first.first == device) {
        write(device, it->second, nullptr);
        it = pending_.erase(it);
      } else {
        ++it;
      }
    }
  }

  // Strokes still waiting for a shape when the stream ends are drawn without one.
  void flush() {
    for (const auto& [key, finished] : pending_) write(key.first, finished, nullptr);
    pending_.clear();
  }

  [[nodiscard]] std::size_t written() const { return written_; }

 private:
  void write(const std::string& device, const v1::StrokeFinished& f, const v1::Shape* shape) {
    const auto path = dir_ / stroke_file_name(device, f.stroke().id());
    try {
      render::write_svg_file(path.string(), render::stroke_svg(stroke_figure(f, shape)));
      ++written_;
    } catch (const std::exception& e) {
      // One bad picture must not end the watch; say why.
      std::fprintf(stderr, "penshape watch: %s: %s\n", path.string().c_str(), e.what());
    }
  }

  std::filesystem::path dir_;
  std::map<std::pair<std::string, std::uint64_t>, v1::StrokeFinished> pending_;
  std::size_t written_ = 0;
};

std::vector<std::string> split_ids(const std::string& text) {
  std::vector<std::string> ids;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    if (comma == start) throw UsageError("option '--device' has an empty device id");
    ids.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return ids;
}

v1::SubscribeRequest watch_request(const ParsedArgs& parsed) {
  v1::SubscribeRequest request;
  request.set_include_samples(parsed.flag("--samples"));
  request.set_include_previews(parsed.flag("--previews"));
  request.set_include_deconstruction(parsed.flag("--deconstructions"));
  if (const auto ids = parsed.value("--device")) {
    for (const auto& id : split_ids(*ids)) request.add_device_ids(id);
  }
  return request;
}

std::optional<SvgArchive> svg_archive(const ParsedArgs& parsed) {
  const auto dir = parsed.value("--svg-dir");
  if (!dir) return std::nullopt;
  std::error_code ec;
  std::filesystem::create_directories(*dir, ec);
  if (ec || !std::filesystem::is_directory(*dir)) {
    throw UsageError("--svg-dir " + *dir + ": cannot create the directory" +
                     (ec ? " (" + ec.message() + ")" : ""));
  }
  return std::optional<SvgArchive>(std::in_place, *dir);
}

// How the subscription ended, as the exit code: a cancel on purpose (--count, Ctrl-C), the
// --duration deadline and the daemon stopping are normal ends.
int watch_exit(const grpc::Status& status, bool on_purpose, bool timed,
               const std::string& address) {
  if (on_purpose) return kExitOk;
  if (timed && status.error_code() == grpc::StatusCode::DEADLINE_EXCEEDED) return kExitOk;
  if (status.ok()) {
    std::fprintf(stderr, "penshape watch: penshaped stopped; the subscription ended\n");
    return kExitOk;
  }
  const RpcFailure failure = describe_rpc_failure(status, "Subscribe", address);
  std::fprintf(stderr, "penshape watch: %s\n", failure.message.c_str());
  return failure.exit_code;
}

} // namespace

int run_watch(std::span<const std::string_view> args) {
  const ParsedArgs parsed(
      args, live_arg_spec(
                {.flags = {"--json", "--samples", "--previews", "--deconstructions", "--devices"},
                 .options = {"--device", "--count", "--duration", "--svg-dir"}}));
  if (parsed.flag("--help")) {
    std::printf(kHelp, kLiveOptionsHelp);
    return kExitOk;
  }
  if (!parsed.positionals().empty()) {
    throw UsageError("unexpected argument '" + parsed.positionals().front() + "'");
  }
  const std::string address = daemon_address(parsed);
  const auto count = parsed.positive_integer("--count");
  const auto duration = parsed.number("--duration");
  if (duration && (*duration <= 0 || *duration > 1e7)) {
    throw UsageError("option '--duration' needs a number of seconds > 0");
  }
  const v1::SubscribeRequest request = watch_request(parsed);
  std::optional<SvgArchive> archive = svg_archive(parsed);
  const bool json = parsed.flag("--json");

  CancelOnSignal cancel; // before any gRPC thread exists
  try {
    auto stub = v1::Live::NewStub(connect_to_daemon(address));
    grpc::ClientContext context;
    if (duration) {
      context.set_deadline(std::chrono::system_clock::now() +
                           std::chrono::microseconds(static_cast<std::int64_t>(*duration * 1e6)));
    }
    auto reader = stub->Subscribe(&context, request);
    const auto armed = cancel.arm(&context);
    reader->WaitForInitialMetadata();
    std::fprintf(stderr, "penshape watch: subscribed to %s (Ctrl-C to stop)\n", address.c_str());
    // Events from both streams print under one lock, and count towards --count together.
    std::mutex output;
    std::uint64_t events = 0;
    bool reached_count = false;
    auto print = [&](const v1::LiveEvent& e) {
      std::lock_guard lock(output);
      if (reached_count) return;
      std::puts((json ? event_json(e) : event_line(e)).c_str());
      std::fflush(stdout);
      if (archive) archive->on_event(e);
      if (count && ++events >= *count) {
        reached_count = true;
        context.TryCancel();
      }
    };
    std::optional<DeviceEvents> device_events;
    if (parsed.flag("--devices")) device_events.emplace(*stub, print);
    v1::LiveEvent event;
    while (reader->Read(&event)) print(event);
    device_events.reset();
    const grpc::Status status = reader->Finish();
    if (archive) {
      archive->flush();
      std::fprintf(stderr, "penshape watch: %zu pictures in %s\n", archive->written(),
                   parsed.value("--svg-dir")->c_str());
    }
    return watch_exit(status, reached_count || cancel.fired(), duration.has_value(), address);
  } catch (const DaemonUnavailable& e) {
    std::fprintf(stderr, "penshape watch: %s\n", e.what());
    return kExitInternal;
  }
}

} // namespace penshape::cli
