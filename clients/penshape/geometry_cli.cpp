#include "geometry_cli.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>

#include "command.hpp"
#include "penshape/core/polygon_io.hpp"

namespace penshape::cli {

std::optional<Rational> optional_rational(const ParsedArgs& parsed, const char* name) {
  const auto text = parsed.value(name);
  if (!text) return std::nullopt;
  try {
    return parse_rational(*text);
  } catch (const InvalidInput&) {
    throw UsageError(std::string("option '") + name + "' needs a number, got '" + *text + "'");
  }
}

Rational required_rational(const ParsedArgs& parsed, const char* name) {
  auto v = optional_rational(parsed, name);
  if (!v) throw UsageError(std::string("option '") + name + "' is required");
  return *v;
}

EngineKind engine_option(const ParsedArgs& parsed) {
  const std::string engine = parsed.value("--engine").value_or("fast");
  if (engine == "fast") return EngineKind::kFast;
  if (engine == "reference") return EngineKind::kReference;
  throw UsageError("option '--engine' must be fast or reference, got '" + engine + "'");
}

namespace {

// The same bound as penshaped's (daemon/include/penshape/daemon/limits.hpp): past it the engines'
// grids and disk approximations stop being meaningful, so such a file is refused up front.
constexpr double kMaxAbsCoordinate = 1e12;

void check_coordinates(const PolygonSet& q) {
  const Rational limit(kMaxAbsCoordinate);
  const Rational negative_limit(-kMaxAbsCoordinate);
  // Compared in place: abs() would build a temporary rational per coordinate.
  const auto beyond = [&](const Rational& v) { return v > limit || v < negative_limit; };
  for (std::size_t i = 0; i < q.polygons.size(); ++i) {
    const auto check_ring = [&](const Ring& ring, const std::string& name) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        if (beyond(ring[k].x) || beyond(ring[k].y)) {
          throw InvalidInput("polygon " + std::to_string(i) + ", " + name + ", vertex " +
                             std::to_string(k) + ": a coordinate beyond the limit of ±1e12");
        }
      }
    };
    check_ring(q.polygons[i].outer, "outer ring");
    for (std::size_t h = 0; h < q.polygons[i].holes.size(); ++h) {
      check_ring(q.polygons[i].holes[h], "hole " + std::to_string(h));
    }
  }
}

// The whole file: one read of its size when it is a regular file (streaming 5.8 MB through a
// stringstream took 10 ms of a 200,000-vertex run), then whatever a pipe (or a file that grew)
// still holds.
std::string read_text_file(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size =
      std::filesystem::is_regular_file(path, error) ? std::filesystem::file_size(path, error) : 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "'");
  std::string text;
  if (!error && size > 0) {
    text.resize(static_cast<std::size_t>(size));
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(in.gcount()));
    in.clear();
  }
  std::ostringstream rest;
  rest << in.rdbuf();
  text += rest.view();
  return text;
}

} // namespace

ValidatedRegion read_valid_polygon_file(const std::string& path) {
  const std::string text = read_text_file(path);
  try {
    PolygonSet q = read_polygon_text(text);
    check_coordinates(q);
    return ValidatedRegion::validate(std::move(q));
  } catch (const InvalidInput& e) {
    throw InputError(path + ": " + e.what());
  }
}

PolygonSet read_polygon_file(const std::string& path) {
  return std::move(read_valid_polygon_file(path)).release();
}

Rational bounding_width(const PolygonSet& q) {
  if (q.empty() || q.polygons[0].outer.empty()) return Rational(0);
  Rational lo = q.polygons[0].outer[0].x;
  Rational hi = lo;
  for (const auto& p : q.polygons) {
    for (const auto& v : p.outer) {
      if (v.x < lo) lo = v.x;
      if (v.x > hi) hi = v.x;
    }
  }
  return hi - lo;
}

namespace {
ReportedSolution reported(SimplifyResult s) {
  ReportedSolution out;
  out.result = std::move(s.result);
  out.raw_vertices = s.raw_vertices;
  out.solution_vertices = s.solution_vertices;
  out.simplified = s.simplified;
  return out;
}
} // namespace

ReportedSolution report_solution(const PolygonSet& q, const DeconstructResult& raw, bool simplify) {
  ReportedSolution out;
  out.result = raw;
  out.raw_vertices = distinct_vertex_count(raw.solution);
  out.solution_vertices = out.raw_vertices;
  if (simplify && raw.answer == Answer::kYes) return reported(simplify_solution(q, raw));
  return out;
}

ReportedSolution decide_and_report(const ValidatedRegion& q, const DeconstructParams& params,
                                   bool simplify) {
  if (!simplify) return report_solution(q.region(), deconstruct(q, params), false);
  return reported(deconstruct_simplified(q, params));
}

namespace {
void ring_json(JsonWriter& json, const Ring& ring) {
  json.begin_array();
  for (const auto& p : ring)
    json.begin_array().number(to_double(p.x)).number(to_double(p.y)).end_array();
  json.end_array();
}
} // namespace

void write_polygon_set(JsonWriter& json, const PolygonSet& set) {
  write_polygons(json, set.polygons, ring_json);
}

void write_solution_keys(JsonWriter& json, const ReportedSolution& s) {
  json.key("solution");
  write_polygon_set(json, s.result.solution);
  json.key("solution_vertices").integer(static_cast<std::int64_t>(s.solution_vertices));
  json.key("raw_vertices").integer(static_cast<std::int64_t>(s.raw_vertices));
  json.key("simplified").boolean(s.simplified);
}

void write_params(JsonWriter& json, const DeconstructParams& params) {
  json.begin_object();
  json.key("radius").number(to_double(params.radius));
  json.key("tolerance").number(to_double(params.tolerance));
  json.key("precision").number(to_double(params.precision));
  json.end_object();
}

void write_certificate_keys(JsonWriter& json, const DeconstructResult& result) {
  json.key("no_witness");
  if (result.no_witness) {
    json.begin_array()
        .number(to_double(result.no_witness->x))
        .number(to_double(result.no_witness->y))
        .end_array();
  } else {
    json.null();
  }
  json.key("exact").begin_object();
  json.key("radius").string(result.params.radius.get_str());
  json.key("tolerance").string(result.params.tolerance.get_str());
  json.key("precision").string(result.params.precision.get_str());
  if (result.answer == Answer::kYes) json.key("solution").string(to_wkt(result.solution));
  if (result.no_witness) {
    json.key("no_witness")
        .begin_array()
        .string(result.no_witness->x.get_str())
        .string(result.no_witness->y.get_str())
        .end_array();
  }
  json.end_object();
}

double seconds(std::chrono::nanoseconds d) { return std::chrono::duration<double>(d).count(); }

int run_on_input_files(const char* name, const std::function<void()>& work) {
  try {
    work();
  } catch (const InputError& e) {
    std::fprintf(stderr, "penshape %s: %s\n", name, e.what());
    return kExitBadInput;
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "penshape %s: %s\n", name, e.what());
    return kExitBadInput;
  }
  return kExitOk;
}

} // namespace penshape::cli
