// `penshape recognize`: the certified stroke recognizer on stroke files (formats in
// stroke_files.hpp), with an optional confusion table against labels.
#include "recognize_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "json_writer.hpp"
#include "penshape/core/ink.hpp"
#include "penshape/core/recognize.hpp"
#include "penshape/render/figure.hpp"
#include "penshape/render/progress_bar.hpp"
#include "stroke_files.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape recognize [--pen-radius R] [--tolerance E] [--ink [--pressure]] [--json]\n"
    "                          [--labels] [--svg-dir DIR] FILE|DIR...\n"
    "\n"
    "Names the shape each stroke was meant to be (segment, polyline, triangle, quadrilateral,\n"
    "rectangle, square, diamond, regular_polygon, circle, ellipse, arc) and snaps only when the\n"
    "clean shape's ink is certified within Hausdorff distance E of the stroke's ink; otherwise\n"
    "`freeform`.\n"
    "\n"
    "Input: $1 gesture logs (.xml: <Gesture Name=...><Point X= Y= T=/>...</Gesture>) and JSON\n"
    "lines (.jsonl/.ndjson, one stroke per line: {\"points\":[[x,y,t],...],\"name\":\"...\",\n"
    "\"label\":\"...\"}, t in seconds and optional; a fourth number is the pen pressure in [0, "
    "1],\n"
    "for every point or none). Directories are searched recursively.\n"
    "\n"
    "  --pen-radius R  pen radius in the file's unit (default: 2% of each drawing's size)\n"
    "  --tolerance E   Hausdorff tolerance (default: min(4.5 R, 10% of the drawing's size))\n"
    "  --ink           certify on the inks: build each stroke's ink polygon with the pen radius\n"
    "                  and certify the snap against it (certificate_method \"ink\"; default:\n"
    "                  \"path\", the pen paths, exact for one pen radius); seconds include it\n"
    "  --pressure      with --ink: the ink's radius follows each point's pressure p,\n"
    "                  R (0.25 + 0.75 p); the clean shape is drawn with the stroke's median\n"
    "                  radius. Needs pressure in the file (JSON lines; $1 XML has none)\n"
    "  --json          one object per stroke: file, line, name, class, confidence, params,\n"
    "                  alternatives, certified, certificate, certificate_method, seconds (and\n"
    "                  label with --labels);\n"
    "                  with --labels a final {\"summary\": ...} object\n"
    "  --labels        expected class from the gesture name (triangle03 -> triangle, circle ->\n"
    "                  circle, rectangle -> rectangle, others -> freeform) or the JSON \"label\";\n"
    "                  prints a confusion table. Accepted as correct: the label itself, and\n"
    "                  circle/ellipse, rectangle/square/quadrilateral, diamond/square.\n"
    "  --svg-dir DIR   one picture per stroke: the samples, their ink and the snapped shape\n"
    "                  with its tolerance band (DIR/<file stem>-<line>.svg)\n"
    "\n"
    "Exit codes: 0 ok, 2 bad input (message names file and line), 1 internal failure.";

std::string label_for(const FileStroke& s) {
  std::string name = s.label.empty() ? s.name : s.label;
  if (shape_class_from_string(name)) return name;
  while (!name.empty() && std::isdigit(static_cast<unsigned char>(name.back()))) name.pop_back();
  if (name == "triangle" || name == "circle" || name == "rectangle") return name;
  return "freeform";
}

bool accepted(const std::string& label, const std::string& got) {
  if (label == got) return true;
  static const std::map<std::string, std::set<std::string>> kFamilies{
      {"circle", {"ellipse"}},
      {"rectangle", {"square", "quadrilateral"}},
      {"square", {"rectangle", "quadrilateral", "diamond"}},
      {"diamond", {"square", "quadrilateral"}},
      {"ellipse", {"circle"}},
  };
  const auto it = kFamilies.find(label);
  return it != kFamilies.end() && it->second.contains(got);
}

void write_point(JsonWriter& json, PointD p) {
  json.begin_array().number(p.x).number(p.y).end_array();
}

void write_params(JsonWriter& json, ShapeClass c, const ShapeParams& p) {
  json.begin_object();
  if (!p.vertices.empty()) {
    json.key("vertices").begin_array();
    for (const PointD& v : p.vertices) write_point(json, v);
    json.end_array();
  }
  if (c == ShapeClass::kFreeform) return void(json.end_object());
  json.key("center");
  write_point(json, p.center);
  if (p.radius_x > 0) json.key("radius_x").number(p.radius_x);
  if (p.radius_y > 0) json.key("radius_y").number(p.radius_y);
  json.key("rotation").number(p.rotation);
  if (c == ShapeClass::kArc) {
    json.key("start_angle").number(p.start_angle);
    json.key("sweep_angle").number(p.sweep_angle);
  }
  json.end_object();
}

void write_certificate(JsonWriter& json, const Certificate& c) {
  json.begin_object();
  json.key("certified").boolean(c.certified);
  json.key("bound").number(c.bound);
  json.key("epsilon").number(c.epsilon);
  json.key("pen_radius").number(c.pen_radius);
  json.key("sample_spacing").number(c.sample_spacing);
  json.key("method").string(c.method);
  json.end_object();
}

// The stroke's ink polygon (radius R, or R (0.25 + 0.75 p) with pressure: ink.hpp's curve with
// its default min_fraction and gamma) and the recognition certified on it. The clean shape's pen
// radius is R, or with pressure the median of the samples' radii.
Recognition recognize_on_ink(const FileStroke& s, const RecognizerConfig& config, bool pressure) {
  const ToleranceChoice tol = choose_tolerance(s.points, config);
  // No size (fewer than two distinct points, or none): the recognizer names the problem.
  if (!(tol.pen_radius > 0) || !std::isfinite(tol.pen_radius)) return recognize(s.points, config);
  InkOptions options;
  options.radius_mm = tol.pen_radius;
  std::vector<InkSample> samples;
  samples.reserve(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    double radius = tol.pen_radius;
    if (pressure) {
      const double p = std::pow(s.pressure[i], options.gamma);
      radius *= options.min_fraction + (1.0 - options.min_fraction) * p;
    }
    samples.push_back({s.points[i].x, s.points[i].y, radius});
  }
  const InkPolygon ink = ink_polygon(samples, options);
  StrokeInput input;
  input.samples = s.points;
  input.ink = &ink;
  if (pressure) {
    std::vector<double> radii;
    for (const InkSample& x : samples) radii.push_back(x.radius);
    std::nth_element(radii.begin(), radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2),
                     radii.end());
    input.pen_radius = radii[radii.size() / 2];
  } else {
    input.pen_radius = tol.pen_radius;
  }
  return recognize(input, config);
}

} // namespace

// The figure of one recognized stroke (input units as "mm": the picture is scale-free).
render::StrokeFigure stroke_figure(const FileStroke& s, const Recognition& r) {
  render::StrokeFigure fig;
  for (const auto& p : s.points) fig.samples.push_back({p.x, p.y});
  fig.pen_radius = r.pen_radius;
  fig.tolerance = r.certificate.certified ? r.epsilon : 0.0;
  fig.caption = (s.name.empty() ? s.file : s.name) + ": " + to_string(r.shape);
  if (r.shape != ShapeClass::kFreeform) {
    render::ShapeOutline o;
    o.label = to_string(r.shape);
    switch (r.shape) {
      case ShapeClass::kCircle:
        o.kind = render::ShapeOutline::Kind::kCircle;
        o.center = r.params.center;
        o.radius = r.params.radius_x;
        break;
      case ShapeClass::kEllipse:
        o.kind = render::ShapeOutline::Kind::kEllipse;
        o.center = r.params.center;
        o.semi_major = r.params.radius_x;
        o.semi_minor = r.params.radius_y;
        o.rotation_rad = r.params.rotation;
        break;
      case ShapeClass::kArc:
        o.kind = render::ShapeOutline::Kind::kArc;
        o.center = r.params.center;
        o.radius = r.params.radius_x;
        o.start_rad = r.params.start_angle;
        o.sweep_rad = r.params.sweep_angle;
        break;
      case ShapeClass::kSegment:
      case ShapeClass::kPolyline:
        o.kind = render::ShapeOutline::Kind::kPolyline;
        o.vertices = r.params.vertices;
        break;
      default:
        o.kind = render::ShapeOutline::Kind::kPolygon;
        o.vertices = r.params.vertices;
        break;
    }
    fig.shape = o;
  }
  return fig;
}

int run_recognize(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, {.flags = {"--json", "--labels", "--ink", "--pressure", "--help"},
                                 .options = {"--pen-radius", "--tolerance", "--svg-dir"}});
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  RecognizerConfig config;
  if (const auto r = parsed.number("--pen-radius")) {
    if (!(*r > 0)) throw UsageError("--pen-radius must be positive");
    config.pen_radius = *r;
  }
  if (const auto e = parsed.number("--tolerance")) {
    if (!(*e > 0)) throw UsageError("--tolerance must be positive");
    config.tolerance = *e;
  }
  if (parsed.positionals().empty()) throw UsageError("no FILE or DIR given");
  const bool on_ink = parsed.flag("--ink");
  const bool pressure = parsed.flag("--pressure");
  if (pressure && !on_ink) throw UsageError("--pressure needs --ink");
  const bool json_out = parsed.flag("--json");
  const bool labels = parsed.flag("--labels");
  const std::optional<std::string> svg_dir = parsed.value("--svg-dir");
  if (svg_dir) {
    std::error_code ec;
    std::filesystem::create_directories(*svg_dir, ec);
    if (ec) {
      std::fprintf(stderr, "penshape recognize: cannot create '%s': %s\n", svg_dir->c_str(),
                   ec.message().c_str());
      return kExitBadInput;
    }
  }

  std::vector<std::string> files;
  try {
    files = collect_stroke_files(parsed.positionals());
  } catch (const StrokeFileError& e) {
    std::fprintf(stderr, "penshape recognize: %s\n", e.what());
    return kExitBadInput;
  }
  // Large directories: a progress bar on the terminal while the results go to a file or pipe
  // (drawn only on a TTY; never mixed into results printed on the same terminal).
  render::ProgressBar bar("recognize", files.size(), stderr,
                          ::isatty(STDOUT_FILENO) != 0 ? render::ProgressBar::Mode::kNever
                                                       : render::ProgressBar::Mode::kAuto);
  std::map<std::string, std::map<std::string, std::size_t>> confusion;
  std::size_t strokes = 0, correct = 0;
  for (const std::string& file : files) {
    bar.advance();
    std::vector<FileStroke> batch;
    try {
      batch = read_stroke_file(file);
    } catch (const StrokeFileError& e) {
      std::fprintf(stderr, "penshape recognize: %s\n", e.what());
      return kExitBadInput;
    }
    for (const FileStroke& s : batch) {
      Recognition r;
      const auto t0 = std::chrono::steady_clock::now();
      try {
        if (on_ink) {
          if (pressure && s.pressure.empty()) {
            std::fprintf(stderr,
                         "penshape recognize: %s:%zu: --pressure: the stroke has no pressure\n",
                         s.file.c_str(), s.line);
            return kExitBadInput;
          }
          r = recognize_on_ink(s, config, pressure);
        } else {
          r = recognize(s.points, config);
        }
      } catch (const InvalidInput& e) {
        std::fprintf(stderr, "penshape recognize: %s:%zu: %s\n", s.file.c_str(), s.line, e.what());
        return kExitBadInput;
      }
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const std::string got = to_string(r.shape);
      if (svg_dir) {
        const std::string name =
            std::filesystem::path(s.file).stem().string() + "-" + std::to_string(s.line) + ".svg";
        try {
          render::write_svg_file((std::filesystem::path(*svg_dir) / name).string(),
                                 render::stroke_svg(stroke_figure(s, r)));
        } catch (const std::runtime_error& e) {
          std::fprintf(stderr, "penshape recognize: %s\n", e.what());
          return kExitBadInput;
        }
      }
      const std::string label = labels ? label_for(s) : "";
      ++strokes;
      if (labels) {
        ++confusion[label][got];
        if (accepted(label, got)) ++correct;
      }
      if (json_out) {
        JsonWriter json;
        json.begin_object();
        json.key("file").string(s.file);
        json.key("line").integer(static_cast<std::int64_t>(s.line));
        json.key("name").string(s.name);
        if (labels) json.key("label").string(label);
        json.key("class").string(got);
        json.key("confidence").number(r.confidence);
        json.key("bound").number(r.certificate.bound);
        json.key("rms").number(r.rms);
        json.key("params");
        write_params(json, r.shape, r.params);
        json.key("alternatives").begin_array();
        for (const Candidate& c : r.alternatives) {
          json.begin_object();
          json.key("class").string(to_string(c.shape));
          json.key("certified").boolean(c.certificate.certified);
          json.key("bound").number(c.certificate.bound);
          json.key("rms").number(c.rms);
          if (!c.rejected.empty()) json.key("rejected").string(c.rejected);
          json.end_object();
        }
        json.end_array();
        json.key("certified").boolean(r.certificate.certified);
        json.key("certificate_method").string(r.certificate.method);
        json.key("certificate");
        write_certificate(json, r.certificate);
        json.key("seconds").number(seconds);
        json.end_object();
        std::puts(json.str().c_str());
      } else {
        std::printf("%s:%zu %s -> %s", s.file.c_str(), s.line, s.name.c_str(), got.c_str());
        if (r.certificate.certified) {
          std::printf(" (confidence %.2f, bound %.3g <= eps %.3g)", r.confidence,
                      r.certificate.bound, r.epsilon);
        }
        if (labels)
          std::printf(" [label %s%s]", label.c_str(), accepted(label, got) ? "" : ", WRONG");
        std::printf(" %.3f ms\n", seconds * 1e3);
      }
    }
  }
  bar.finish();
  if (labels) {
    std::set<std::string> columns;
    for (const auto& [label, row] : confusion) {
      for (const auto& [got, n] : row) columns.insert(got);
    }
    if (json_out) {
      JsonWriter json;
      json.begin_object().key("summary").begin_object();
      json.key("strokes").integer(static_cast<std::int64_t>(strokes));
      json.key("correct").integer(static_cast<std::int64_t>(correct));
      json.key("confusion").begin_object();
      for (const auto& [label, row] : confusion) {
        json.key(label).begin_object();
        for (const auto& [got, n] : row) json.key(got).integer(static_cast<std::int64_t>(n));
        json.end_object();
      }
      json.end_object().end_object().end_object();
      std::puts(json.str().c_str());
    } else {
      std::printf("\n%-12s", "label\\class");
      for (const auto& c : columns) std::printf(" %10.10s", c.c_str());
      std::printf(" %8s\n", "correct");
      for (const auto& [label, row] : confusion) {
        std::size_t total = 0, ok = 0;
        std::printf("%-12s", label.c_str());
        for (const auto& c : columns) {
          const auto it = row.find(c);
          const std::size_t n = it == row.end() ? 0 : it->second;
          total += n;
          if (accepted(label, c)) ok += n;
          std::printf(" %10zu", n);
        }
        std::printf(" %7.1f%%\n",
                    total ? 100.0 * static_cast<double>(ok) / static_cast<double>(total) : 0.0);
      }
      std::printf(
          "overall: %zu / %zu correct (%.1f%%)\n", correct, strokes,
          strokes ? 100.0 * static_cast<double>(correct) / static_cast<double>(strokes) : 0.0);
    }
  }
  return kExitOk;
}

} // namespace penshape::cli
