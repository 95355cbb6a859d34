// Radius suggestion from the local maxima of J(r) = r / ε̂(r) (Section 4, the Flower example).
#include <algorithm>
#include <chrono>

#include "penshape/core/search.hpp"

namespace penshape {

SuggestResult suggest_radius(const Decider& decide, const SuggestOptions& options) {
  if (sgn(options.from) <= 0 || options.to <= options.from) {
    throw InvalidInput("radius range must satisfy 0 < from < to, got [" + options.from.get_str() +
                       ", " + options.to.get_str() + "]");
  }
  if (options.samples < 3) throw InvalidInput("suggest needs at least 3 samples");
  if (sgn(options.relative_precision) <= 0 || options.relative_precision >= 1) {
    throw InvalidInput("relative precision must be in (0, 1)");
  }
  const auto start = std::chrono::steady_clock::now();
  SuggestResult out;
  std::vector<DeconstructResult> solutions;
  const Rational step =
      (options.to - options.from) / Rational(static_cast<unsigned long>(options.samples - 1));
  for (std::size_t i = 0; i < options.samples; ++i) {
    const Rational r = options.from + step * Rational(static_cast<unsigned long>(i));
    ToleranceSearchResult t =
        search_tolerance(decide, r, r * options.relative_precision, options.fallback);
    out.decider_calls += t.decider_calls;
    RadiusSample s{r, t.eps_low, t.eps_high, 0.0};
    s.j = sgn(t.eps_high) > 0 ? to_double(r / t.eps_high) : 0.0;
    out.samples.push_back(s);
    solutions.push_back(std::move(t.solution));
    if (options.progress && !options.progress(i + 1, options.samples)) {
      out.stopped_early = true;
      break;
    }
  }
  const std::size_t n = out.samples.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double j = out.samples[i].j;
    if (j >= out.samples[i - 1].j && j > out.samples[i + 1].j) {
      out.suggestions.push_back({out.samples[i], solutions[i]});
    }
  }
  if (out.suggestions.empty() && n > 0) { // monotone J: the best end of the range
    const auto best = std::max_element(out.samples.begin(), out.samples.end(),
                                       [](const auto& a, const auto& b) { return a.j < b.j; });
    const auto k = static_cast<std::size_t>(best - out.samples.begin());
    out.suggestions.push_back({out.samples[k], solutions[k]});
  }
  std::sort(out.suggestions.begin(), out.suggestions.end(),
            [](const auto& a, const auto& b) { return a.sample.j > b.sample.j; });
  out.elapsed = std::chrono::steady_clock::now() - start;
  return out;
}

} // namespace penshape
