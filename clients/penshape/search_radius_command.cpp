// `penshape search-radius FILE --tolerance E`: the radii with a solution form [0, r*]; bounds
// on r*, with the certified solution at the lower bound.
#include <cstdio>
#include <string>

#include "command.hpp"
#include "geometry_cli.hpp"
#include "penshape/core/search.hpp"
#include "search_commands.hpp"

namespace penshape::cli {

int run_search_radius(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args,
                          {.flags = {"--json", "--help", "--no-simplify"},
                           .options = {"--tolerance", "--precision", "--engine", "--max-calls"}});
  if (parsed.flag("--help")) {
    std::puts(
        "usage: penshape search-radius FILE --tolerance E [--precision P] [--max-calls N]\n"
        "                              [--engine fast|reference] [--no-simplify] [--json]\n\n"
        "The radii R for which FILE is within Hausdorff distance E of an R-offset form an\n"
        "interval [0, r*]. Prints r* in [r_low, r_high]: r_low has a certified solution, r_high\n"
        "a certified NO (or the a-priori bound). Stops at width P (default E/4) or after N\n"
        "decider calls (default 200): persistent UNDECIDED answers can leave it unconverged.\n"
        "--json keys: tolerance, r_low, r_high, converged, solution, solution_vertices,\n"
        "raw_vertices, simplified, decider_calls, undecided_calls, seconds, engine.\n"
        "Exit codes: 0 ok, 2 bad input, 1 internal failure.");
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) throw UsageError("expected exactly one FILE");
  const Rational tolerance = required_rational(parsed, "--tolerance");
  RadiusSearchOptions opt;
  opt.precision = optional_rational(parsed, "--precision").value_or(tolerance / 4);
  if (const auto calls = parsed.number("--max-calls")) {
    if (*calls < 1 || *calls > 100000)
      throw UsageError("option '--max-calls' must be in [1, 100000]");
    opt.max_decider_calls = static_cast<std::size_t>(*calls);
  }
  const EngineKind engine = engine_option(parsed);
  return run_on_input_files("search-radius", [&] {
    const PolygonSet q = read_polygon_file(parsed.positionals().front());
    const RadiusSearchResult res = search_radius(make_decider(q, engine), tolerance,
                                                 enclosing_radius_bound(q) + tolerance, opt);
    const ReportedSolution rep =
        report_solution(q, res.solution_at_low, !parsed.flag("--no-simplify"));
    if (parsed.flag("--json")) {
      JsonWriter json;
      json.begin_object();
      json.key("tolerance").number(to_double(tolerance));
      json.key("r_low").number(to_double(res.r_low));
      json.key("r_high").number(to_double(res.r_high));
      json.key("converged").boolean(res.converged);
      write_solution_keys(json, rep);
      json.key("decider_calls").integer(static_cast<std::int64_t>(res.decider_calls));
      json.key("undecided_calls").integer(static_cast<std::int64_t>(res.undecided_calls));
      json.key("seconds").number(seconds(res.elapsed));
      json.key("engine").string(to_string(engine));
      json.end_object();
      std::puts(json.str().c_str());
    } else {
      std::printf("r* in [%.9g, %.9g]%s (tolerance %g)\n", to_double(res.r_low),
                  to_double(res.r_high), res.converged ? "" : " (not converged)",
                  to_double(tolerance));
      std::printf("certified solution at r = %.9g: %zu vertices (raw %zu)\n", to_double(res.r_low),
                  rep.solution_vertices, rep.raw_vertices);
      std::printf("%zu decider calls (%zu undecided), %.3f s\n", res.decider_calls,
                  res.undecided_calls, seconds(res.elapsed));
    }
  });
}

} // namespace penshape::cli
