// `penshape suggest-radius FILE [--from --to --samples]`: local maxima of J(r) = r / ε̂(r)
// (the paper's Flower example), each with its certified solution. Progress on stderr.
#include <unistd.h>

#include <cstdio>
#include <functional>
#include <optional>
#include <string>

#include "command.hpp"
#include "geometry_cli.hpp"
#include "penshape/core/search.hpp"
#include "penshape/render/progress_bar.hpp"
#include "search_commands.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape suggest-radius FILE [--from R0] [--to R1] [--samples N]\n"
    "                               [--engine fast|reference] [--no-simplify] [--quiet] "
    "[--json]\n\n"
    "Samples J(r) = r / eps_hat(r) at N radii (default 20) in [R0, R1] (default w/100 to\n"
    "w/5, w the bounding-box width) and suggests the radii at its local maxima, best first,\n"
    "each with a certified solution. Progress goes to stderr (--quiet silences it).\n"
    "--json keys: samples [{radius, eps_low, eps_high, j}], suggestions [{radius, eps, j,\n"
    "solution, solution_vertices, raw_vertices, simplified}], decider_calls, seconds.\n"
    "Exit codes: 0 ok, 2 bad input, 1 internal failure.";

// Progress on stderr: a bar on a terminal; plain lines in logs and pipes, so scripts still see
// progress; nothing with --quiet. `bar` holds the terminal's bar (finish it at the end).
std::function<bool(std::size_t, std::size_t)> progress_reporter(
    bool show, std::size_t samples, std::optional<render::ProgressBar>& bar) {
  if (show && ::isatty(STDERR_FILENO) != 0) bar.emplace("suggest-radius", samples);
  return [show, &bar](std::size_t done, std::size_t total) {
    if (bar) {
      bar->update(done);
    } else if (show) {
      std::fprintf(stderr, "suggest-radius: %zu/%zu radii\n", done, total);
    }
    return true;
  };
}

void print_json(const PolygonSet& q, const SuggestResult& res, bool simplify) {
  JsonWriter json;
  json.begin_object();
  json.key("samples").begin_array();
  for (const auto& s : res.samples) {
    json.begin_object();
    json.key("radius").number(to_double(s.radius));
    json.key("eps_low").number(to_double(s.eps_low));
    json.key("eps_high").number(to_double(s.eps_high));
    json.key("j").number(s.j);
    json.end_object();
  }
  json.end_array();
  json.key("suggestions").begin_array();
  for (const auto& s : res.suggestions) {
    json.begin_object();
    json.key("radius").number(to_double(s.sample.radius));
    json.key("eps").number(to_double(s.solution.params.tolerance));
    json.key("j").number(s.sample.j);
    write_solution_keys(json, report_solution(q, s.solution, simplify));
    json.end_object();
  }
  json.end_array();
  json.key("decider_calls").integer(static_cast<std::int64_t>(res.decider_calls));
  json.key("seconds").number(seconds(res.elapsed));
  json.end_object();
  std::puts(json.str().c_str());
}

void print_text(const PolygonSet& q, const SuggestResult& res, bool simplify) {
  std::printf("%12s %14s %14s %10s\n", "radius", "eps_low", "eps_high", "J");
  for (const auto& s : res.samples) {
    std::printf("%12.6g %14.6g %14.6g %10.4g\n", to_double(s.radius), to_double(s.eps_low),
                to_double(s.eps_high), s.j);
  }
  for (const auto& s : res.suggestions) {
    const ReportedSolution rep = report_solution(q, s.solution, simplify);
    std::printf("suggested radius %.6g (J = %.4g): solution at eps %.6g, %zu vertices\n",
                to_double(s.sample.radius), s.sample.j, to_double(s.solution.params.tolerance),
                rep.solution_vertices);
  }
  std::printf("%zu decider calls, %.3f s\n", res.decider_calls, seconds(res.elapsed));
}

} // namespace

int run_suggest_radius(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, {.flags = {"--json", "--help", "--no-simplify", "--quiet"},
                                 .options = {"--from", "--to", "--samples", "--engine"}});
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) throw UsageError("expected exactly one FILE");
  const EngineKind engine = engine_option(parsed);
  return run_on_input_files("suggest-radius", [&] {
    const PolygonSet q = read_polygon_file(parsed.positionals().front());
    const Rational w = bounding_width(q);
    SuggestOptions opt;
    opt.from = optional_rational(parsed, "--from").value_or(w / 100);
    opt.to = optional_rational(parsed, "--to").value_or(w / 5);
    if (const auto n = parsed.number("--samples")) {
      if (*n < 3 || *n > 1000) throw UsageError("option '--samples' must be in [3, 1000]");
      opt.samples = static_cast<std::size_t>(*n);
    }
    std::optional<render::ProgressBar> bar;
    opt.progress = progress_reporter(!parsed.flag("--quiet"), opt.samples, bar);
    // The reference engine settles what the fast engine leaves UNDECIDED against its promise.
    if (engine == EngineKind::kFast) opt.fallback = make_decider(q, EngineKind::kReference);
    const SuggestResult res = suggest_radius(make_decider(q, engine), opt);
    if (bar) bar->finish();
    const bool simplify = !parsed.flag("--no-simplify");
    (parsed.flag("--json") ? print_json : print_text)(q, res, simplify);
  });
}

} // namespace penshape::cli
