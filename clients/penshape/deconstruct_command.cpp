// `penshape deconstruct FILE --radius R --tolerance E [--precision D] [--engine fast|reference]
// [--json]`: offset deconstruction of a polygon file (x-y or WKT), offline.
#include "deconstruct_command.hpp"

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "geometry_cli.hpp"
#include "json_writer.hpp"
#include "penshape/core/arc_offset.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/polygon_io.hpp"
#include "penshape/core/validated_region.hpp"
#include "penshape/render/figure.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape deconstruct FILE --radius R --tolerance E [--precision D]\n"
    "                            [--engine fast|reference] [--no-simplify] [--json] [--arcs]\n"
    "                            [--svg OUT.svg]\n\n"
    "Is the region in FILE within Hausdorff distance E of the R-offset of some polygonal\n"
    "region P? Answers YES (with P), NO or UNDECIDED (precision D too coarse), certified.\n"
    "FILE: x-y text (`x y` per line, `#` comments, blank line between rings) or WKT POLYGON /\n"
    "MULTIPOLYGON. Numbers are read exactly. D defaults to E/8; the engine to fast, which\n"
    "asks the reference engine itself when its grid loses a feature thinner than a grid unit\n"
    "and it cannot decide; `engine` (text and --json) names the engine that answered.\n"
    "A YES solution is simplified (fewer vertices, still certified) unless --no-simplify.\n"
    "--svg draws Q, P, offset(P, R) with true arcs and the E-band, like the paper's figures.\n\n"
    "--json prints one object: answer, engine (fast or reference: the one that answered),\n"
    "seconds (engine time), solution (list of\n"
    "{\"outer\": [[x,y],...], \"holes\": [[[x,y],...],...]}), solution_vertices, raw_vertices\n"
    "(before simplification), simplified, input_vertices,\n"
    "hausdorff_bound (null unless YES), disk_vertices, params {radius, tolerance, precision},\n"
    "no_witness ([x,y] with NO: a point of the input no solution can serve, else null), exact\n"
    "{radius, tolerance, precision as exact rationals, solution as exact WKT with YES,\n"
    "no_witness as two exact rationals with NO} (what `penshape verify` checks).\n"
    "--arcs adds offset(P, R) with true arcs (with YES): \"offset\": [{\"outer\": [curve...],\n"
    "\"holes\": [[curve...]...]}], a curve being {\"segment\": [[x,y],[x,y]]} or {\"arc\":\n"
    "{\"center\": [x,y], \"radius\": R, \"start\": [x,y], \"end\": [x,y]}} (counterclockwise),\n"
    "and \"offset_max_error\"; as text it prints the curve counts.\n"
    "Exit codes: 0 answered (any answer), 2 bad input, 1 internal failure.";

// A large input's stages each allocate and free buffers of megabytes: glibc hands freed blocks
// over its (adaptive) mmap threshold and a freed heap top over 128 KiB back to the system, and
// the next stage takes a page fault per 4 KiB again (7,000 of a 200,000-vertex run's 24,000).
// This process is short-lived: blocks up to 32 MiB (glibc's largest threshold) come from the
// heap, and up to 64 MiB of freed heap stays for reuse.
void keep_freed_memory() {
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
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
  json.key("offset");
  write_polygons(json, region.polygons, curves_json);
  json.key("offset_max_error").number(region.max_error);
}

void print_json(const ReportedSolution& rep, std::size_t input_vertices, const CurvedRegion* arcs) {
  const DeconstructResult& res = rep.result;
  JsonWriter json;
  json.begin_object();
  json.key("answer").string(to_string(res.answer));
  json.key("engine").string(to_string(res.engine));
  json.key("seconds").number(seconds(res.elapsed));
  write_solution_keys(json, rep);
  json.key("input_vertices").integer(static_cast<std::int64_t>(input_vertices));
  json.key("hausdorff_bound");
  if (res.answer == Answer::kYes) {
    json.number(to_double(res.hausdorff_bound));
  } else {
    json.null();
  }
  json.key("disk_vertices").integer(static_cast<std::int64_t>(res.disk_vertices));
  json.key("params");
  write_params(json, res.params);
  write_certificate_keys(json, res);
  if (arcs != nullptr) offset_json(json, *arcs);
  json.end_object();
  std::puts(json.str().c_str());
}

void print_text(const ReportedSolution& rep, std::size_t input_vertices, const CurvedRegion* arcs) {
  const DeconstructResult& res = rep.result;
  std::printf("answer: %s\nengine: %s\nseconds: %.6f\ninput vertices: %zu\n", to_string(res.answer),
              to_string(res.engine), std::chrono::duration<double>(res.elapsed).count(),
              input_vertices);
  std::printf("radius %g, tolerance %g, precision %g, disk vertices %zu\n",
              to_double(res.params.radius), to_double(res.params.tolerance),
              to_double(res.params.precision), res.disk_vertices);
  if (res.answer == Answer::kYes) {
    std::printf("hausdorff bound: %g\nsolution vertices: %zu (raw %zu%s)\nsolution: %s\n",
                to_double(res.hausdorff_bound), rep.solution_vertices, rep.raw_vertices,
                rep.simplified ? ", simplified" : "", to_wkt(res.solution).c_str());
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
  const ParsedArgs parsed(
      args, {.flags = {"--json", "--help", "--arcs", "--simplify", "--no-simplify"},
             .options = {"--radius", "--tolerance", "--precision", "--engine", "--svg"}});
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) throw UsageError("expected exactly one FILE");
  const std::string path = parsed.positionals().front();

  DeconstructParams params;
  params.radius = required_rational(parsed, "--radius");
  params.tolerance = required_rational(parsed, "--tolerance");
  params.precision = optional_rational(parsed, "--precision").value_or(params.tolerance / 8);
  params.engine = engine_option(parsed);
  keep_freed_memory();
  try {
    const ValidatedRegion valid = read_valid_polygon_file(path); // validated once, here
    const PolygonSet& q = valid.region();
    const ReportedSolution rep = decide_and_report(valid, params, !parsed.flag("--no-simplify"));
    std::optional<CurvedRegion> arcs;
    if (parsed.flag("--arcs") && rep.result.answer == Answer::kYes) {
      arcs = offset_with_arcs(rep.result.solution, to_double(params.radius));
    }
    const CurvedRegion* arcs_ptr = arcs ? &*arcs : nullptr;
    if (const auto svg = parsed.value("--svg")) {
      // Q, P, offset(P, r) with true arcs and the ε-band, like the paper's figures.
      render::write_svg_file(
          *svg, render::deconstruction_svg(render::deconstruction_figure(q, rep.result)));
    }
    if (parsed.flag("--json")) {
      print_json(rep, q.vertex_count(), arcs_ptr);
    } else {
      print_text(rep, q.vertex_count(), arcs_ptr);
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "penshape deconstruct: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::runtime_error& e) { // the SVG file could not be written
    std::fprintf(stderr, "penshape deconstruct: %s\n", e.what());
    return kExitBadInput;
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "penshape deconstruct: %s: %s\n", path.c_str(), e.what());
    return kExitBadInput;
  }
  return kExitOk;
}

} // namespace penshape::cli
