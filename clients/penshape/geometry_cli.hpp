#pragma once
// What the offline geometry subcommands share: exact numeric options, the engine option,
// reading a polygon file, simplifying a solution, and the JSON shapes of solutions.
#include <chrono>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "args.hpp"
#include "json_writer.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/simplify.hpp"
#include "penshape/core/validated_region.hpp"

namespace penshape::cli {

// Bad input that is not a usage error (unreadable or malformed file): exit code 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An option read exactly (decimal or p/q); UsageError when missing (required) or malformed.
Rational required_rational(const ParsedArgs& parsed, const char* name);
std::optional<Rational> optional_rational(const ParsedArgs& parsed, const char* name);

// --engine fast|reference (default fast).
EngineKind engine_option(const ParsedArgs& parsed);

// x-y text or WKT, checked as a region (validate_region) with coordinates within ±1e12 (as
// penshaped's limit); InputError naming the file (and line) when unreadable or malformed.
PolygonSet read_polygon_file(const std::string& path);
// The same, as a ValidatedRegion: deconstruct() then does not validate the region again.
ValidatedRegion read_valid_polygon_file(const std::string& path);

// Width of the bounding box (x extent); 0 for an empty set.
Rational bounding_width(const PolygonSet& q);

// The solution a subcommand reports: simplified (when asked and when it helps) with the vertex
// counts before and after.
struct ReportedSolution {
  DeconstructResult result;
  std::size_t raw_vertices = 0;
  std::size_t solution_vertices = 0;
  bool simplified = false;
};
ReportedSolution report_solution(const PolygonSet& q, const DeconstructResult& raw, bool simplify);
// The same for a deconstruction of a validated region: with `simplify`, through
// deconstruct_simplified (the simplifier reuses the decision's grid and certified input).
ReportedSolution decide_and_report(const ValidatedRegion& q, const DeconstructParams& params,
                                   bool simplify);

// [{"outer": RING, "holes": [RING, ...]}, ...] for polygons with an outer ring and holes (of
// points, or of curves), each RING written by `write_ring`.
template <typename Polygons, typename WriteRing>
void write_polygons(JsonWriter& json, const Polygons& polygons, WriteRing write_ring) {
  json.begin_array();
  for (const auto& p : polygons) {
    json.begin_object();
    json.key("outer");
    write_ring(json, p.outer);
    json.key("holes").begin_array();
    for (const auto& h : p.holes) write_ring(json, h);
    json.end_array();
    json.end_object();
  }
  json.end_array();
}

// write_polygons with rings of points: [[x,y],...].
void write_polygon_set(JsonWriter& json, const PolygonSet& set);
// "solution", "solution_vertices", "raw_vertices", "simplified" keys of a reported solution.
void write_solution_keys(JsonWriter& json, const ReportedSolution& s);
// {"radius": r, "tolerance": e, "precision": d}
void write_params(JsonWriter& json, const DeconstructParams& params);

// "no_witness": [x, y] or null, and "exact": {"radius", "tolerance", "precision" as exact
// rationals ("p/q" or integer text), "solution" as exact WKT (YES only), "no_witness" as two
// exact rationals (NO only)}: what `penshape verify` re-checks without double rounding.
void write_certificate_keys(JsonWriter& json, const DeconstructResult& result);

double seconds(std::chrono::nanoseconds d);

// Runs the work of subcommand `name` on its files: an unreadable or malformed file (InputError)
// or an invalid region (InvalidInput) prints "penshape NAME: why" on stderr and gives
// kExitBadInput; otherwise kExitOk.
int run_on_input_files(const char* name, const std::function<void()>& work);

} // namespace penshape::cli
