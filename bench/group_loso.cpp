// Leave-one-subject-out figures for the grouping thresholds picked on real strokes
// (group_loso.hpp).
#include "group_loso.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "group_gesture_figures.hpp"
#include "recognize/arrow/fit_arrow.hpp"
#include "recognize/group/group_plausibility.hpp"

namespace penshape::bench {
namespace {

using recognize_detail::arrow_rules;
using recognize_detail::group_rules;

// A threshold the library reads at run time, the values tried and the one shipped.
struct Knob {
  const char* name;
  std::vector<double> values;
  double shipped;
  std::function<void(double)> set;
};

struct Counts {
  int hits = 0, total = 0;
  void add(const Counts& c) { hits += c.hits, total += c.total; }
  [[nodiscard]] double percent() const { return total ? 100.0 * hits / total : 0.0; }
};

// One writer's figures at one value: shapes right, non-shape drawings snapped together.
struct WriterCounts {
  Counts shapes, non_shapes;
};
using BySubject = std::map<std::string, WriterCounts>;

BySubject score_all(const std::vector<Drawing>& drawings) {
  BySubject out;
  for (const Drawing& d : drawings) {
    const GestureKind kind = gesture_kind(d);
    if (kind == GestureKind::kNone || kind == GestureKind::kChevron) continue;
    const bool hit = gesture_hit(kind, recognize_gesture(d));
    Counts& c = kind == GestureKind::kNonShape ? out[d.subject].non_shapes : out[d.subject].shapes;
    c.hits += hit ? 1 : 0, ++c.total;
  }
  return out;
}

// The figures of every writer but `left_out` (none: all of them).
WriterCounts others(const BySubject& by, const std::string& left_out) {
  WriterCounts w;
  for (const auto& [s, c] : by) {
    if (s == left_out) continue;
    w.shapes.add(c.shapes);
    w.non_shapes.add(c.non_shapes);
  }
  return w;
}

// The value chosen without `left_out`: most shapes right among those snapping <= 2% of the
// non-shape drawings (the shipped value on ties, else the first).
std::size_t choose(const Knob& k, const std::vector<BySubject>& runs, const std::string& left_out) {
  std::size_t best = k.values.size();
  int best_hits = -1;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const WriterCounts w = others(runs[i], left_out);
    if (w.non_shapes.percent() > 2.0) continue;
    const bool better =
        w.shapes.hits > best_hits || (w.shapes.hits == best_hits && k.values[i] == k.shipped);
    if (better) best = i, best_hits = w.shapes.hits;
  }
  return best < k.values.size() ? best : 0;
}

void print_line(const std::string& what, const WriterCounts& w, bool json) {
  if (json) {
    std::printf("{\"row\":\"%s\",\"shapes_percent\":%.2f,\"non_shapes_snapped_percent\":%.2f}\n",
                what.c_str(), w.shapes.percent(), w.non_shapes.percent());
  } else {
    std::printf("  %-42s shapes right %5.1f%% (%d / %d), non-shapes snapped %4.1f%% (%d / %d)\n",
                what.c_str(), w.shapes.percent(), w.shapes.hits, w.shapes.total,
                w.non_shapes.percent(), w.non_shapes.hits, w.non_shapes.total);
  }
}

void sweep(const Knob& k, const std::vector<Drawing>& drawings, bool json) {
  std::vector<BySubject> runs;
  for (const double v : k.values) {
    k.set(v);
    runs.push_back(score_all(drawings));
    char what[96];
    std::snprintf(what, sizeof what, "%s = %g%s, all writers", k.name, v,
                  v == k.shipped ? " (shipped)" : "");
    print_line(what, others(runs.back(), {}), json);
  }
  k.set(k.shipped);
  WriterCounts held_out;
  std::map<double, int> chosen;
  for (const auto& [subject, c] : runs.front()) {
    const std::size_t i = choose(k, runs, subject);
    ++chosen[k.values[i]];
    const WriterCounts& w = runs[i].at(subject);
    held_out.shapes.add(w.shapes);
    held_out.non_shapes.add(w.non_shapes);
  }
  print_line(std::string(k.name) + ", leave-one-subject-out", held_out, json);
  if (json) return;
  std::printf("  %-42s", "    value chosen (writers)");
  for (const auto& [v, n] : chosen) std::printf(" %g: %d", v, n);
  std::printf("\n");
}

} // namespace

void print_group_loso(const std::filesystem::path& gestures_root, bool json,
                      const std::string& only) {
  std::vector<Drawing> drawings;
  for (Drawing& d : load_gestures(gestures_root)) {
    if (gesture_kind(d) != GestureKind::kNone) drawings.push_back(std::move(d));
  }
  if (drawings.empty()) return;
  const std::vector<Knob> knobs{
      {"kMaxSeparateHeadBarb",
       {1.0, 1.5, 2.0, 2.5, 3.0},
       recognize_detail::kMaxSeparateHeadBarb,
       [](double v) { arrow_rules().max_apart_barb = v; }},
      {"kMinShaftSpan",
       {0.0, 0.3, 0.5, 0.7},
       recognize_detail::kMinShaftSpan,
       [](double v) { arrow_rules().min_shaft_span = v; }},
      {"kMaxContinuationAngle (deg)",
       {30.0, 45.0, 60.0, 75.0},
       std::round(recognize_detail::kMaxContinuationAngle / recognize_detail::kDegree),
       [](double v) { group_rules().max_continuation_angle = v * recognize_detail::kDegree; }},
      {"kMinCornerTurnShare",
       {0.3, 0.35, 0.4, 0.45, 0.5},
       recognize_detail::kMinCornerTurnShare,
       [](double v) { group_rules().min_corner_turn_share = v; }},
      {"kMaxGapBarb",
       {0.7, 1.0, 1.3, 1.6},
       recognize_detail::kMaxGapBarb,
       [](double v) { arrow_rules().max_gap_barb = v; }},
      {"kApartJoin",
       {0.0, 1.0, 2.0, 3.0},
       recognize_detail::kApartJoin,
       [](double v) { group_rules().apart_join = v; }},
      {"kMaxGapAim (deg)",
       {8.0, 12.0, 16.0, 20.0},
       std::round(recognize_detail::kMaxGapAim / recognize_detail::kDegree),
       [](double v) { arrow_rules().max_gap_aim = v * recognize_detail::kDegree; }}};
  if (!json) {
    std::printf(
        "\nleave-one-subject-out on other people's drawings (squares and arrows of several "
        "strokes, non-shape drawings; each value chosen on the other writers):\n");
  }
  for (const Knob& k : knobs) {
    if (std::string(k.name).starts_with(only)) sweep(k, drawings, json);
  }
}

} // namespace penshape::bench
