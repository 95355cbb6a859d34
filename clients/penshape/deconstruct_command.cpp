// `penshape deconstruct FILE --radius R --tolerance E [--precision D] [--engine fast|reference]
// [--json]`: offset deconstruction of a polygon file (x-y or WKT), offline.
#include "deconstruct_command.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "json_writer.hpp"
#include "penshape/core/arc_offset.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape deconstruct FILE --radius R --tolerance E [--precision D]\n"
    "                            [--engine fast|reference] [--json] [--arcs]\n\n"
    "Is the region in FILE within Hausdorff distance E of the R-offset of some polygonal\n"
    "region P? Answers YES (with P), NO or UNDECIDED (precision D too coarse), certified.\n"
    "FILE: x-y text (`x y` per line, `#` comments, blank line between rings) or WKT POLYGON /\n"
    "MULTIPOLYGON. Numbers are read exactly. D defaults to E/8; the engine to fast.\n\n"
    "--json prints one object: answer, engine, seconds (engine time), solution (list of\n"
    "{\"outer\": [[x,y],...], \"holes\": [[[x,y],...],...]}), solution_vertices, input_vertices,\n"
    "hausdorff_bound (null unless YES), disk_vertices, params {radius, tolerance, precision}.\n"
    "--arcs adds offset(P, R) with true arcs (with YES): \"offset\": [{\"outer\": [curve...],\n"
    "\"holes\": [[curve...]...]}], a curve being {\"segment\": [[x,y],[x,y]]} or {\"arc\":\n"
    "{\"center\": [x,y], \"radius\": R, \"start\": [x,y], \"end\": [x,y]}} (counterclockwise),\n"
    "and \"offset_max_error\"; as text it prints the curve counts.\n"
    "Exit codes: 0 answered (any answer), 2 bad input, 1 internal failure.";

Rational required_rational(const ParsedArgs& parsed, const char* name) {
  const auto text = parsed.value(name);
  if (!text) throw UsageError(std::string("option '") + name + "' is required");
  try {
    return parse_rational(*text);
  } catch (const InvalidInput&) {
    throw UsageError(std::string("option '") + name + "' needs a number, got '" + *text + "'");
  }
}

void ring_json(JsonWriter& json, const Ring& ring) {
  json.begin_array();
  for (const auto& p : ring) {
    json.begin_array().number(to_double(p.x)).number(to_double(p.y)).end_array();
  }
  json.end_array();
}

void point_json(JsonWriter& json, PointD p) {
  json.begin_array().number(p.x).number(p.y).end_array();
}

void curves_json(JsonWriter& json, const CurveRing& ring) {
  json.begin_array();
  for (const auto& c : ring.curves) {
    json.begin_object();
    if (c.kind == BoundaryCurve::Kind::kSegment) {
      json.key("segment").begin_array();
      point_json(json, c.start);
      point_json(json, c.end);
      json.end_array();
    } else {
      json.key("arc").begin_object();
      json.key("center");
      point_json(json, c.center);
      json.key("radius").number(c.radius);
      json.key("start");
      point_json(json, c.start);
      json.key("end");
      point_json(json, c.end);
      json.end_object();
    }
    json.end_object();
  }
  json.end_array();
}

void offset_json(JsonWriter& json, const CurvedRegion& region) {
  json.key("offset").begin_array();
  for (const auto& p : region.polygons) {
    json.begin_object();
    json.key("outer");
    curves_json(json, p.outer);
    json.key("holes").begin_array();
    for (const auto& h : p.holes) curves_json(json, h);
    json.end_array();
    json.end_object();
  }
  json.end_array();
  json.key("offset_max_error").number(region.max_error);
}

void print_json(const DeconstructResult& res, std::size_t input_vertices,
                const CurvedRegion* arcs) {
  JsonWriter json;
  json.begin_object();
  json.key("answer").string(to_string(res.answer));
  json.key("engine").string(to_string(res.engine));
  json.key("seconds").number(std::chrono::duration<double>(res.elapsed).count());
  json.key("solution").begin_array();
  for (const auto& p : res.solution.polygons) {
    json.begin_object();
    json.key("outer");
    ring_json(json, p.outer);
    json.key("holes").begin_array();
    for (const auto& h : p.holes) ring_json(json, h);
    json.end_array();
    json.end_object();
  }
  json.end_array();
  json.key("solution_vertices").integer(static_cast<std::int64_t>(res.solution.vertex_count()));
  json.key("input_vertices").integer(static_cast<std::int64_t>(input_vertices));
  json.key("hausdorff_bound");
  if (res.answer == Answer::kYes) {
    json.number(to_double(res.hausdorff_bound));
  } else {
    json.null();
  }
  json.key("disk_vertices").integer(static_cast<std::int64_t>(res.disk_vertices));
  json.key("params").begin_object();
  json.key("radius").number(to_double(res.params.radius));
  json.key("tolerance").number(to_double(res.params.tolerance));
  json.key("precision").number(to_double(res.params.precision));
  json.end_object();
  if (arcs != nullptr) offset_json(json, *arcs);
  json.end_object();
  std::puts(json.str().c_str());
}

void print_text(const DeconstructResult& res, std::size_t input_vertices,
                const CurvedRegion* arcs) {
  std::printf("answer: %s\nengine: %s\nseconds: %.6f\ninput vertices: %zu\n", to_string(res.answer),
              to_string(res.engine), std::chrono::duration<double>(res.elapsed).count(),
              input_vertices);
  std::printf("radius %g, tolerance %g, precision %g, disk vertices %zu\n",
              to_double(res.params.radius), to_double(res.params.tolerance),
              to_double(res.params.precision), res.disk_vertices);
  if (res.answer == Answer::kYes) {
    std::printf("hausdorff bound: %g\nsolution vertices: %zu\nsolution: %s\n",
                to_double(res.hausdorff_bound), res.solution.vertex_count(),
                to_wkt(res.solution).c_str());
  }
  if (arcs != nullptr) {
    std::size_t segments = 0;
    std::size_t arc_count = 0;
    auto count = [&](const CurveRing& ring) {
      for (const auto& c : ring.curves) {
        (c.kind == BoundaryCurve::Kind::kArc ? arc_count : segments) += 1;
      }
    };
    for (const auto& p : arcs->polygons) {
      count(p.outer);
      for (const auto& h : p.holes) count(h);
    }
    std::printf("offset(P, r): %zu segments, %zu arcs (max error %g)\n", segments, arc_count,
                arcs->max_error);
  }
}

} // namespace

int run_deconstruct(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args,
                          {.flags = {"--json", "--help", "--arcs"},
                           .options = {"--radius", "--tolerance", "--precision", "--engine"}});
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) throw UsageError("expected exactly one FILE");
  const std::string path = parsed.positionals().front();

  DeconstructParams params;
  params.radius = required_rational(parsed, "--radius");
  params.tolerance = required_rational(parsed, "--tolerance");
  params.precision = parsed.value("--precision") ? required_rational(parsed, "--precision")
                                                 : Rational(params.tolerance / 8);
  const std::string engine = parsed.value("--engine").value_or("fast");
  if (engine == "fast") {
    params.engine = EngineKind::kFast;
  } else if (engine == "reference") {
    params.engine = EngineKind::kReference;
  } else {
    throw UsageError("option '--engine' must be fast or reference, got '" + engine + "'");
  }

  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "penshape deconstruct: cannot read '%s'\n", path.c_str());
    return kExitBadInput;
  }
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const PolygonSet q = read_polygon_text(text.str());
    const DeconstructResult res = deconstruct(q, params);
    std::optional<CurvedRegion> arcs;
    if (parsed.flag("--arcs") && res.answer == Answer::kYes) {
      arcs = offset_with_arcs(res.solution, to_double(params.radius));
    }
    const CurvedRegion* arcs_ptr = arcs ? &*arcs : nullptr;
    if (parsed.flag("--json")) {
      print_json(res, q.vertex_count(), arcs_ptr);
    } else {
      print_text(res, q.vertex_count(), arcs_ptr);
    }
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "penshape deconstruct: %s: %s\n", path.c_str(), e.what());
    return kExitBadInput;
  }
  return kExitOk;
}

} // namespace penshape::cli
