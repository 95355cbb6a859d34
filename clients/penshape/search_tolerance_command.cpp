// `penshape search-tolerance FILE --radius R [--precision Δ]`: the smallest tolerance ε̂ for
// which the polygon is an approximate R-offset, to within Δ, with a certified solution.
#include <cstdio>
#include <string>

#include "command.hpp"
#include "geometry_cli.hpp"
#include "penshape/core/search.hpp"
#include "search_commands.hpp"

namespace penshape::cli {

int run_search_tolerance(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, {.flags = {"--json", "--help", "--no-simplify"},
                                 .options = {"--radius", "--precision", "--engine"}});
  if (parsed.flag("--help")) {
    std::puts(
        "usage: penshape search-tolerance FILE --radius R [--precision D] [--engine "
        "fast|reference]\n"
        "                                 [--no-simplify] [--json]\n\n"
        "Finds an interval [eps_low, eps_high] of width <= D (default R/100) holding the\n"
        "smallest tolerance for which FILE is within that Hausdorff distance of an R-offset\n"
        "(APPROXSEARCHEPS), and a certified solution at eps_solution <= that tolerance + D.\n"
        "The fast engine can stay UNDECIDED far from that tolerance (features narrower than\n"
        "the working precision); the search then redoes itself with the reference engine. If a\n"
        "search still cannot converge it prints the interval its YES and NO answers prove\n"
        "(wider than D) and says so: 'not converged' on stderr, converged false in --json.\n"
        "--json keys: radius, eps_low, eps_high, eps_solution, answer, solution, "
        "solution_vertices,\n"
        "raw_vertices, simplified, decider_calls, fallback_calls, converged, note, seconds,\n"
        "engine.\n"
        "Exit codes: 0 ok (converged or not), 2 bad input, 1 internal failure.");
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) throw UsageError("expected exactly one FILE");
  const Rational radius = required_rational(parsed, "--radius");
  const Rational precision = optional_rational(parsed, "--precision").value_or(radius / 100);
  const EngineKind engine = engine_option(parsed);
  return run_on_input_files("search-tolerance", [&] {
    const PolygonSet q = read_polygon_file(parsed.positionals().front());
    // The reference engine settles what the fast engine leaves UNDECIDED against its promise.
    const Decider fallback =
        engine == EngineKind::kFast ? make_decider(q, EngineKind::kReference) : Decider{};
    const ToleranceSearchResult res =
        search_tolerance(make_decider(q, engine), radius, precision, fallback);
    const ReportedSolution rep = report_solution(q, res.solution, !parsed.flag("--no-simplify"));
    if (parsed.flag("--json")) {
      JsonWriter json;
      json.begin_object();
      json.key("radius").number(to_double(radius));
      json.key("eps_low").number(to_double(res.eps_low));
      json.key("eps_high").number(to_double(res.eps_high));
      json.key("eps_solution").number(to_double(res.solution.params.tolerance));
      json.key("answer").string(to_string(res.solution.answer));
      write_solution_keys(json, rep);
      json.key("decider_calls").integer(static_cast<std::int64_t>(res.decider_calls));
      json.key("fallback_calls").integer(static_cast<std::int64_t>(res.fallback_calls));
      json.key("converged").boolean(res.converged);
      json.key("note").string(res.note);
      json.key("seconds").number(seconds(res.elapsed));
      json.key("engine").string(to_string(engine));
      json.end_object();
      std::puts(json.str().c_str());
    } else {
      std::printf("eps_hat in [%.9g, %.9g] (radius %g)\n", to_double(res.eps_low),
                  to_double(res.eps_high), to_double(radius));
      std::printf("certified solution at eps %.9g: %zu vertices (raw %zu)\n",
                  to_double(res.solution.params.tolerance), rep.solution_vertices,
                  rep.raw_vertices);
      std::printf("%zu decider calls (%zu by the reference fallback), %.3f s\n", res.decider_calls,
                  res.fallback_calls, seconds(res.elapsed));
    }
    if (!res.note.empty()) {
      std::fprintf(stderr, "penshape search-tolerance: %s%s\n",
                   res.converged ? "note: " : "not converged: ", res.note.c_str());
    }
  });
}

} // namespace penshape::cli
