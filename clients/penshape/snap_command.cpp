// `penshape snap IN OUT`: the snap library (clients/snap) on files, through penshaped when it
// answers, else in-process.
#include "snap_command.hpp"

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "args.hpp"
#include "command.hpp"
#include "daemon_channel.hpp"
#include "json_writer.hpp"
#include "snap/atomic_file.hpp"
#include "snap/daemon_recognizer.hpp"
#include "snap/progress_bar.hpp"
#include "snap/snap_document.hpp"
#include "snap/snap_error.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape snap [--json] [--quiet] [--pen-radius R] [--tolerance E] [--no-group]\n"
    "                     [--snap-writing] [--ids ID,...] [--layer ID]\n"
    "                     [--local | --socket S | --address A]\n"
    "                     IN OUT | --in-place IN\n"
    "\n"
    "Replaces each pen stroke of a drawing that the recognizer certifies by its clean shape, as a\n"
    "native element of the drawing's format, at the same place (layer and z-order). Everything\n"
    "else (text, images, other layers, pages, backgrounds, metadata, unrecognized strokes) stays.\n"
    "\n"
    "Input, by content (not extension):\n"
    "  SVG (Inkscape or plain): stroked, unfilled path/polyline/polygon/line elements (pen\n"
    "    radius: half the stroke width; a closed subpath keeps its closing side) and filled,\n"
    "    unstroked one-piece paths of nearly constant width (Calligraphy outlines: pen path and\n"
    "    radius estimated from the outline). Each layer is one page.\n"
    "  Xournal++ .xopp (gzip XML, or the zip package with content.xml and attachments): pen and\n"
    "    highlighter strokes, with pressure widths read as Xournal++ reads them (a width <= 0\n"
    "    draws nothing). Each layer of each page is one page.\n"
    "  A dot (one point) is left as drawn; an element snap cannot read as a stroke (bad numbers,\n"
    "  widths, transforms, coordinates beyond 1e6) is left as drawn with a warning naming it.\n"
    "Output: SVG rect, circle, ellipse, line, polyline, polygon or path with true arcs, keeping\n"
    "  id, style, transform, with data-penshape-class and data-penshape-certificate; .xopp\n"
    "  strokes with the original's tool and colour, of the clean pen's width (a pressure\n"
    "  stroke keeps its width profile; curves as polylines within the certificate's tolerance).\n"
    "  Open shapes run the way they were drawn (markers stay at their ends). Only replaced\n"
    "  elements change: every other byte of the document is written back as it was.\n"
    "\n"
    "  --pen-radius R  pen radius in document units (default: each stroke's: half its width,\n"
    "                  the median for pressure strokes)\n"
    "  --tolerance E   Hausdorff tolerance in document units (default: the recognizer's rule,\n"
    "                  min(0.125 S + R, 0.135 S), S the diagonal of the stroke's or group's\n"
    "                  bounding box: it follows the drawing, not the pen); runs in-process\n"
    "  --no-group      recognize every stroke on its own (default: strokes drawn one after the\n"
    "                  other that together make one shape, such as a rectangle's four sides or\n"
    "                  an arrow's shaft and head, become that shape, certified on their union;\n"
    "                  document order is drawing order; all of the group's strokes are replaced;\n"
    "                  only strokes of the same tool, colour, markers and width (within 10%)\n"
    "                  are grouped)\n"
    "  --snap-writing  snap handwriting too (default: each page's strokes are judged writing or\n"
    "                  drawing in drawing order, as `penshape recognize` does, with the page's\n"
    "                  unit in mm: SVG user units from the root's width and viewBox, else CSS\n"
    "                  pixels; .xopp points; writing strokes are never snapped nor grouped and\n"
    "                  stay byte for byte); for drawings with no writing on them\n"
    "  --ids ID,...    only these elements (a group or layer: what it holds); SVG only\n"
    "  --layer ID      only this layer; SVG only\n"
    "  --in-place      write the result over IN (IN is never overwritten otherwise)\n"
    "  --local         recognize in this process even when penshaped is running\n"
    "  --json          one object per replacement: elements (stable locators: the id, else an\n"
    "                  XPath-like path such as \"/xournal/page[1]/layer[1]/stroke[3]\"; several\n"
    "                  for a group), where, class, params, tidy (the tidy-up constraints\n"
    "                  applied), pen_radius, certificate, intent; then one object per stroke\n"
    "                  read: element, where, intent (\"writing\" or \"drawing\"), writing_score\n"
    "                  (P(writing)); then one {\"warning\": ...} per element left as drawn\n"
    "  --quiet         no progress bar and no warnings (the bar shows on stderr when a run\n"
    "                  takes over a second, never with --json)\n"
    "  --socket PATH   penshaped's unix socket (default: $XDG_RUNTIME_DIR/penshape.sock)\n"
    "  --address ADDR  a gRPC address instead (unix:PATH, unix-abstract:NAME, HOST:PORT)\n"
    "Without --local, penshaped's Geometry.Recognize is used when it answers (up to 64 strokes "
    "per\n"
    "call, grouped by the daemon), else the core in-process (a note on stderr says which). OUT is "
    "written to a temporary file and renamed,\n"
    "so no partial file is left; OUT \"-\" is standard output.\n"
    "\n"
    "Pages are recognized in parallel on all cores.\n"
    "\n"
    "Exit codes: 0 ok (also when elements were left as drawn), 2 a document the apps cannot open\n"
    "either (not XML, neither format, corrupt or truncated compression, XML past 1 GiB; the\n"
    "message names the line; OUT is not written), 1 internal failure.";

std::vector<std::string> split_ids(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string id; std::getline(in, id, ',');) {
    if (!id.empty()) out.push_back(id);
  }
  return out;
}

std::string read_input(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw snap::SnapInputError("cannot read " + path);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_point(JsonWriter& json, PointD p) {
  json.begin_array().number(p.x).number(p.y).end_array();
}

std::string json_line(const snap::Replacement& rep) {
  const Recognition& r = rep.recognition;
  JsonWriter json;
  json.begin_object();
  json.key("elements").begin_array();
  for (const auto& e : rep.elements) json.string(e);
  json.end_array().key("where").begin_array();
  for (const auto& w : rep.where) json.string(w);
  json.end_array();
  json.key("class").string(to_string(r.shape));
  json.key("params").begin_object();
  if (!r.params.vertices.empty()) {
    json.key("vertices").begin_array();
    for (const PointD& v : r.params.vertices) write_point(json, v);
    json.end_array();
  }
  json.key("center");
  write_point(json, r.params.center);
  if (r.params.radius_x > 0) json.key("radius_x").number(r.params.radius_x);
  if (r.params.radius_y > 0) json.key("radius_y").number(r.params.radius_y);
  json.key("rotation").number(r.params.rotation);
  if (r.shape == ShapeClass::kArc) {
    json.key("start_angle").number(r.params.start_angle);
    json.key("sweep_angle").number(r.params.sweep_angle);
  }
  if (r.params.head_angle > 0) json.key("head_angle").number(r.params.head_angle);
  if (r.shape == ShapeClass::kArrow || r.shape == ShapeClass::kDoubleArrow) {
    json.key("shaft_bulge").number(r.params.shaft_bulge);
    json.key("shaft_bends").begin_array();
    for (const PointD& b : r.params.shaft_bends) write_point(json, b);
    json.end_array();
    if (r.params.shaft_end) {
      json.key("shaft_end");
      write_point(json, *r.params.shaft_end);
    }
  }
  json.end_object();
  json.key("tidy").begin_array();
  for (const auto& t : rep.tidy) json.string(t);
  json.end_array();
  json.key("pen_radius").number(rep.pen_radius);
  const Certificate& c = r.certificate;
  json.key("certificate").begin_object();
  json.key("certified").boolean(c.certified).key("bound").number(c.bound);
  json.key("epsilon").number(c.epsilon).key("pen_radius").number(c.pen_radius);
  json.key("method").string(c.method).end_object();
  json.key("intent").string(to_string(rep.intent));
  json.end_object();
  return json.str();
}

std::string json_line(const snap::StrokeIntent& s) {
  JsonWriter json;
  json.begin_object().key("element").string(s.element).key("where").string(s.where);
  json.key("intent").string(to_string(s.decision.intent));
  json.key("writing_score").number(s.decision.writing_score).end_object();
  return json.str();
}

// penshaped's recognizer when it answers (and nothing asks for in-process), else the core's.
// A page the daemon fails on is recognized in-process, with a note; once the daemon is gone, every
// later page too.
snap::PageRecognizer choose_recognizer(const ParsedArgs& parsed, std::string& engine) {
  snap::PageRecognizer local = snap::recognize_page_in_process;
  engine = "in-process";
  if (parsed.flag("--local")) return local;
  const std::string address = daemon_address(parsed);
  if (parsed.number("--tolerance")) {
    std::fprintf(stderr,
                 "penshape snap: --tolerance: recognizing in-process (penshaped's "
                 "Recognize takes no tolerance)\n");
    return local;
  }
  std::shared_ptr<grpc::Channel> channel;
  try {
    channel = connect_to_daemon(address, std::chrono::milliseconds(1500));
  } catch (const DaemonUnavailable& e) {
    std::fprintf(stderr, "penshape snap: %s; recognizing in-process\n", e.what());
    return local;
  }
  engine = "penshaped at " + address;
  auto remote = snap::daemon_recognizer(channel);
  auto failed = std::make_shared<std::atomic<bool>>(false); // pages run on several threads
  return [remote, local, failed](const std::vector<snap::InkStroke>& page,
                                 const snap::SnapSettings& settings) {
    if (!*failed) {
      try {
        return remote(page, settings);
      } catch (const snap::DaemonCallFailed& e) {
        std::fprintf(stderr, "penshape snap: %s; recognizing in-process\n", e.what());
        if (e.unavailable) *failed = true;
      }
    }
    return local(page, settings);
  };
}

// Each element left as drawn: a line on stderr, or a {"warning": ...} object with --json.
void report_warnings(const std::vector<std::string>& warnings, bool json, bool quiet) {
  for (const std::string& w : warnings) {
    if (json) {
      JsonWriter out;
      out.begin_object().key("warning").string(w).end_object();
      std::puts(out.str().c_str());
    } else if (!quiet) {
      std::fprintf(stderr, "penshape snap: warning: %s\n", w.c_str());
    }
  }
}

// How many strokes were judged writing and left as drawn (a line on stderr).
void report_writing(const snap::SnapResult& result, bool snap_writing, bool quiet) {
  std::size_t writing = 0;
  for (const snap::StrokeIntent& s : result.intents) {
    writing += s.decision.intent == Intent::kWriting ? 1 : 0;
  }
  if (writing == 0 || snap_writing || quiet) return;
  std::fprintf(stderr,
               "penshape snap: %zu stroke(s) judged writing, left as drawn (--snap-writing "
               "snaps them too)\n",
               writing);
}

struct Paths {
  std::string in, out;
};

Paths in_and_out(const ParsedArgs& parsed) {
  const auto& pos = parsed.positionals();
  if (parsed.flag("--in-place")) {
    if (pos.size() != 1) throw UsageError("--in-place takes exactly one file, IN");
    return {pos[0], pos[0]};
  }
  if (pos.size() != 2) throw UsageError("give IN and OUT (or --in-place IN)");
  std::error_code ec;
  if (pos[1] != "-" && std::filesystem::equivalent(pos[0], pos[1], ec)) {
    throw UsageError("OUT is IN: give --in-place to overwrite IN");
  }
  return {pos[0], pos[1]};
}

snap::SnapOptions options_from(const ParsedArgs& parsed) {
  snap::SnapOptions options;
  if (const auto r = parsed.number("--pen-radius")) {
    if (!(*r > 0) || *r > snap::kMaxStrokeWidth / 2) {
      throw UsageError("--pen-radius must be positive and at most 500");
    }
    options.settings.pen_radius = *r;
  }
  if (const auto e = parsed.number("--tolerance")) {
    if (!(*e > 0)) throw UsageError("--tolerance must be positive");
    options.settings.tolerance = *e;
  }
  options.settings.group = !parsed.flag("--no-group");
  options.settings.snap_writing = parsed.flag("--snap-writing");
  if (const auto ids = parsed.value("--ids")) options.scope.ids = split_ids(*ids);
  if (const auto layer = parsed.value("--layer")) options.scope.layer = *layer;
  return options;
}

} // namespace

int run_snap(std::span<const std::string_view> args) {
  const ParsedArgs parsed(
      args, live_arg_spec({.flags = {"--json", "--quiet", "--no-group", "--in-place", "--local",
                                     "--snap-writing"},
                           .options = {"--pen-radius", "--tolerance", "--ids", "--layer"}}));
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  const Paths paths = in_and_out(parsed);
  snap::SnapOptions options = options_from(parsed);
  const bool json = parsed.flag("--json");
  if (json && paths.out == "-") throw UsageError("--json needs OUT to be a file, not -");
  const bool quiet = parsed.flag("--quiet");
  auto progress = std::make_shared<snap::SnapProgress>();
  if (!quiet && !json)
    options.progress = [progress](auto done, auto total) { (*progress)(done, total); };
  std::string engine;
  snap::SnapResult result;
  try {
    const std::string bytes = read_input(paths.in);
    const snap::PageRecognizer recognizer = choose_recognizer(parsed, engine);
    result = snap::snap_document(bytes, options, recognizer);
  } catch (const snap::SnapInputError& e) {
    progress->finish();
    std::fprintf(stderr, "penshape snap: %s: %s\n", paths.in.c_str(), e.what());
    return kExitBadInput;
  }
  progress->finish();
  try {
    if (paths.out == "-") {
      std::cout.write(result.output.data(), static_cast<std::streamsize>(result.output.size()));
      std::cout.flush();
    } else {
      snap::write_file_atomically(paths.out, result.output);
    }
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "penshape snap: %s\n", e.what());
    return kExitBadInput;
  }
  for (const snap::Replacement& rep : result.replacements) {
    if (json) {
      std::puts(json_line(rep).c_str());
      continue;
    }
    const Certificate& c = rep.recognition.certificate;
    std::fprintf(paths.out == "-" ? stderr : stdout,
                 "%s: %s (H <= %.3g <= eps %.3g, pen r %.3g, %s)\n", rep.where.front().c_str(),
                 to_string(rep.recognition.shape), c.bound, c.epsilon, c.pen_radius,
                 c.method.c_str());
  }
  if (json) {
    for (const snap::StrokeIntent& s : result.intents) std::puts(json_line(s).c_str());
  }
  report_warnings(result.warnings, json, quiet);
  std::fprintf(stderr, "penshape snap: %zu of %zu strokes snapped (%s) -> %s\n",
               result.replacements.size(), result.strokes, engine.c_str(), paths.out.c_str());
  report_writing(result, options.settings.snap_writing, quiet);
  return kExitOk;
}

} // namespace penshape::cli
