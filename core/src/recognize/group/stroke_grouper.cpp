// StrokeGrouper and recognize_strokes(): which recent strokes a new stroke is recognized with
// (group_recognize.hpp, "Grouping"), then tidy-up.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "penshape/core/group_recognize.hpp"
#include "recognize/fitting/dot.hpp"
#include "recognize/fitting/prepared_stroke.hpp"
#include "recognize/fitting/thin_path.hpp"
#include "recognize/group/group_classifier.hpp"
#include "recognize/group/group_plausibility.hpp"
#include "recognize/group/stroke_chain.hpp"
#include "recognize/group/union_tolerance.hpp"
#include "recognize/thresholds.hpp"
#include "recognize/tidy/tidy.hpp"

namespace penshape {
namespace {

using recognize_detail::kMaxGroupStrokes;
using recognize_detail::kMaxRecentGroups;
using recognize_detail::kTouchThinning;
using recognize_detail::UnionRecognition;

// A stroke's touch path (what unions test for touching) and the slack its thinning allows;
// `Touch` is StrokeGrouper's kept form (path, slack, gaps).
template <typename Touch>
Touch touch_path(const std::vector<StrokePoint>& samples) {
  std::vector<PointD> p;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  PointD lo{kInf, kInf}, hi{-kInf, -kInf};
  for (const StrokePoint& s : samples) {
    const PointD q{s.x, s.y};
    if (p.empty() || !(p.back() == q)) p.push_back(q);
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
  }
  const double tau = kTouchThinning * distance(lo, hi);
  Touch out;
  out.path = recognize_detail::thin_path(p, tau);
  out.slack = tau;
  out.lo = lo;
  out.hi = hi;
  return out;
}

// Whether the strokes form one connected graph when strokes within `join` are linked; `gap(i, j)`
// is the gap between strokes i and j.
template <typename Gap>
bool connected(std::size_t n, const std::vector<double>& slack, double join, Gap&& gap) {
  std::vector<bool> seen(n, false);
  std::vector<std::size_t> stack{0};
  seen[0] = true;
  std::size_t count = 1;
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    for (std::size_t j = 0; j < n; ++j) {
      if (seen[j]) continue;
      if (gap(i, j) <= join + slack[i] + slack[j]) {
        seen[j] = true;
        ++count;
        stack.push_back(j);
      }
    }
  }
  return count == n;
}

bool snaps(const Recognition& r) { return r.shape != ShapeClass::kFreeform; }

// The stroke's path and pen radius only: what unions and the kept strokes need (no ink).
StrokeInput path_only(const StrokeInput& stroke) {
  StrokeInput out;
  out.samples = stroke.samples;
  out.pen_radius = stroke.pen_radius;
  return out;
}

// Every non-empty subset of the recent groups (bit k: recent[k]), most strokes first: once a
// union of n strokes snaps, smaller unions cannot win and are not recognized at all.
template <typename Entries>
std::vector<std::size_t> masks_by_size(const std::vector<std::size_t>& recent,
                                       const Entries& groups) {
  std::vector<std::pair<std::size_t, std::size_t>> sized; // (strokes, mask)
  for (std::size_t mask = 1; mask < (std::size_t{1} << recent.size()); ++mask) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < recent.size(); ++k) {
      if (mask & (std::size_t{1} << k)) n += groups[recent[k]].shape.strokes.size();
    }
    sized.emplace_back(n, mask);
  }
  std::stable_sort(sized.begin(), sized.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::size_t> out;
  out.reserve(sized.size());
  for (const auto& [n, mask] : sized) out.push_back(mask);
  return out;
}

// When the previous stroke ended (-inf before the first): the pen-up pause before a stroke is
// measured from it.
template <typename Entries>
double previous_end(const Entries& groups) {
  double end = -std::numeric_limits<double>::infinity();
  for (const auto& e : groups) end = std::max(end, e.end_time);
  return end;
}

// Whether a stroke starting at `start` ends the run of strokes drawn without a longer pause than
// max_pause_seconds: the strokes before it then never join it nor any later stroke. The pause is
// the pen-up before each stroke, not the time since a group's own last stroke: a square's first
// side may stand alone (no open polyline groups) while the next sides follow without a pause.
template <typename Entries>
bool after_long_pause(const Entries& groups, const GroupingConfig& grouping, double start) {
  return start - previous_end(groups) > grouping.max_pause_seconds;
}

// Indices of the recent groups that may still grow with a stroke starting at `start`, newest
// first (at most kMaxRecentGroups); none for a dot or without grouping.
template <typename Entries>
std::vector<std::size_t> growable_groups(const Entries& groups, const GroupingConfig& grouping,
                                         double start, bool dot) {
  std::vector<std::size_t> recent;
  if (!grouping.enabled || dot || after_long_pause(groups, grouping, start)) return recent;
  for (std::size_t g = groups.size(); g-- > 0 && recent.size() < kMaxRecentGroups;) {
    const auto& e = groups[g];
    if (!e.joinable) continue;
    if (e.shape.strokes.size() + 1 > grouping.max_strokes) continue;
    recent.push_back(g);
  }
  return recent;
}

// The strokes' touch paths and the gaps between them: the kept strokes' are kept by the grouper
// across add() calls (each thinned and measured once, the unions tried share most pairs), the
// new stroke's are made once per add(). polyline_gap is symmetric (a minimum over both
// directions, and an exact crossing test), so a pair is one entry, under the later stroke.
template <typename Touches> // StrokeGrouper's touches_
class TouchCache {
 public:
  using Touch = typename Touches::mapped_type;
  static constexpr std::size_t kOwn = std::numeric_limits<std::size_t>::max(); // the new stroke

  TouchCache(Touches& kept, const std::map<std::size_t, StrokeInput>& strokes,
             const StrokeInput& stroke)
      : kept_(kept), strokes_(strokes), own_(touch_path<Touch>(stroke.samples)) {}
  Touch& of(std::size_t s) {
    if (s == kOwn) return own_;
    auto it = kept_.find(s);
    if (it == kept_.end()) it = kept_.emplace(s, touch_path<Touch>(strokes_.at(s).samples)).first;
    return it->second;
  }
  // The gap between the touch paths of strokes a and b (kOwn: the new stroke).
  double gap(std::size_t a, std::size_t b) {
    const std::size_t later = std::max(a, b); // kOwn is the largest
    const std::size_t earlier = std::min(a, b);
    Touch& t = of(later);
    auto it = t.gaps.find(earlier);
    if (it == t.gaps.end()) {
      const double g = recognize_detail::polyline_gap(of(earlier).path, t.path);
      it = t.gaps.emplace(earlier, g).first;
    }
    return it->second;
  }
  // The new stroke's touch (path, slack, gaps measured), for the grouper to keep.
  Touch take_own() { return std::move(own_); }

 private:
  Touches& kept_;
  const std::map<std::size_t, StrokeInput>& strokes_;
  Touch own_;
};

// The best union of recent groups with the new stroke: the most strokes, then the best rank,
// among those that snap, touch end to end and are drawn as that shape is drawn in pieces.
struct BestUnion {
  std::optional<UnionRecognition> best;
  std::vector<std::size_t> groups; // indices into the grouper's groups absorbed
};

struct UnionContext {
  const StrokeInput& stroke;
  const RecognizerConfig& config;     // with the stroke's pen radius
  const RecognizerConfig& recognizer; // the grouper's own
  const GroupingConfig& grouping;
  const std::map<std::size_t, StrokeInput>& strokes;
};

template <typename Entries, typename Touches>
BestUnion best_union(const UnionContext& c, const std::vector<std::size_t>& recent,
                     const Entries& groups, TouchCache<Touches>& touches) {
  BestUnion out;
  std::size_t best_count = 2;
  for (const std::size_t mask : masks_by_size(recent, groups)) {
    std::vector<std::size_t> members;
    std::vector<std::size_t> chosen;
    for (std::size_t k = 0; k < recent.size(); ++k) {
      if (!(mask & (std::size_t{1} << k))) continue;
      chosen.push_back(recent[k]);
      const auto& s = groups[recent[k]].shape.strokes;
      members.insert(members.end(), s.begin(), s.end());
    }
    if (members.size() + 1 > c.grouping.max_strokes || members.size() + 1 < best_count) continue;
    std::sort(members.begin(), members.end());
    std::vector<std::size_t> keys(members); // the touch cache's keys of the union's strokes
    keys.push_back(TouchCache<Touches>::kOwn);
    std::vector<double> slack;
    std::vector<recognize_detail::SampleBox> boxes;
    slack.reserve(keys.size());
    boxes.reserve(keys.size());
    for (const std::size_t k : keys) {
      const auto& t = touches.of(k);
      slack.push_back(t.slack);
      boxes.push_back({t.lo, t.hi});
    }
    const ToleranceChoice tol = recognize_detail::union_tolerance(boxes, c.config);
    const auto gap = [&](std::size_t i, std::size_t j) { return touches.gap(keys[i], keys[j]); };
    const double join = 2.0 * tol.pen_radius + tol.epsilon;
    // Two strokes apart may still be an arrow whose shaft stops short (group_plausibility.hpp).
    const double apart = recognize_detail::apart_join(keys.size(), tol.epsilon);
    const bool touching = connected(keys.size(), slack, join, gap);
    if (!touching && !(apart > 0.0 && connected(keys.size(), slack, join + apart, gap))) continue;
    // Only a connected union is recognized: its strokes are copied then only.
    std::vector<StrokeInput> inputs;
    inputs.reserve(keys.size());
    for (const std::size_t s : members) inputs.push_back(c.strokes.at(s));
    inputs.push_back(path_only(c.stroke));
    const auto use = touching ? recognize_detail::UnionUse::kAnyShape
                              : recognize_detail::UnionUse::kSingleArrowOnly;
    UnionRecognition u = recognize_detail::recognize_union_detail(inputs, c.recognizer, use);
    if (!snaps(u.recognition)) continue;
    std::vector<const StrokeInput*> others; // the recent strokes outside the union
    for (const auto& [k, kept] : c.strokes) {
      if (!std::binary_search(members.begin(), members.end(), k)) others.push_back(&kept);
    }
    if (!recognize_detail::keep_union(u, inputs, others, c.config)) continue;
    if (!touching && !recognize_detail::kept_apart(u.recognition)) continue;
    const std::size_t count = members.size() + 1;
    if (!out.best || count > best_count || (count == best_count && u.rank < out.best->rank)) {
      out.best = std::move(u);
      best_count = count;
      out.groups = std::move(chosen);
    }
  }
  return out;
}

// Recent shapes (newest first, at most max_strokes) that connection and parallelism refer to.
template <typename Entries>
std::vector<const Recognition*> neighbour_shapes(const Entries& groups, std::size_t max_strokes) {
  std::vector<const Recognition*> neighbours;
  for (std::size_t g = groups.size(); g-- > 0 && neighbours.size() < max_strokes;) {
    const Recognition& n = groups[g].shape.recognition;
    if (snaps(n) && n.shape != ShapeClass::kDot) neighbours.push_back(&n); // a dot aligns nothing
  }
  return neighbours;
}

} // namespace

StrokeGrouper::StrokeGrouper(GroupingConfig grouping, RecognizerConfig recognizer)
    : grouping_(grouping), recognizer_(recognizer) {
  if (grouping_.max_strokes < 1 || grouping_.max_strokes > kMaxGroupStrokes ||
      !(grouping_.max_pause_seconds >= 0.0) || !std::isfinite(grouping_.max_pause_seconds)) {
    throw InvalidInput(
        "grouping: max_strokes must be within [1, 8] and max_pause_seconds a "
        "finite number >= 0");
  }
}

void StrokeGrouper::forget_stroke(std::size_t index) {
  strokes_.erase(index);
  touches_.erase(index);
}

void StrokeGrouper::clear() {
  strokes_.clear();
  touches_.clear();
  groups_.clear();
  added_ = 0;
}

void StrokeGrouper::forget_unreachable() {
  std::vector<bool> keep(groups_.size(), false);
  std::size_t growable = 0;
  std::size_t snapped = 0;
  for (std::size_t g = groups_.size(); g-- > 0;) {
    Entry& e = groups_[g];
    // add() tries at most kMaxRecentGroups joinable groups, the newest first.
    if (e.joinable && e.shape.strokes.size() < grouping_.max_strokes &&
        growable < kMaxRecentGroups) {
      ++growable;
      keep[g] = true;
    } else if (e.joinable) {
      e.joinable = false;
      for (const std::size_t i : e.shape.strokes) forget_stroke(i);
    }
    // Tidy-up refers to the last max_strokes shapes that snapped, once add() has removed the
    // (at most kMaxRecentGroups) groups the new stroke absorbs.
    if (snaps(e.shape.recognition) && snapped < grouping_.max_strokes + kMaxRecentGroups) {
      ++snapped;
      keep[g] = true;
    }
  }
  std::size_t kept = 0;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    if (!keep[g]) continue;
    if (kept != g) groups_[kept] = std::move(groups_[g]); // never moved onto itself
    ++kept;
  }
  groups_.resize(kept);
}

std::vector<GroupedShape> StrokeGrouper::shapes() const {
  std::vector<GroupedShape> out;
  for (const Entry& e : groups_) out.push_back(e.shape);
  std::sort(out.begin(), out.end(), [](const GroupedShape& a, const GroupedShape& b) {
    return a.strokes.front() < b.strokes.front();
  });
  return out;
}

GroupUpdate StrokeGrouper::add(const StrokeInput& stroke) {
  RecognizerConfig config = recognizer_;
  if (stroke.pen_radius > 0) config.pen_radius = stroke.pen_radius;
  recognize_detail::validate_samples(stroke.samples, config);
  const std::size_t index = added_;
  const double start = stroke.samples.front().t;
  const bool dot = recognize_detail::is_dot(stroke.samples); // never joins other strokes
  const bool new_run = after_long_pause(groups_, grouping_, start);

  // The best union with recent groups that snaps; else the new stroke alone (ink certificate
  // when its ink is given), arrows included.
  TouchCache touches(touches_, strokes_, stroke);
  BestUnion chosen = best_union({stroke, config, recognizer_, grouping_, strokes_},
                                growable_groups(groups_, grouping_, start, dot), groups_, touches);
  std::vector<std::size_t>& best_groups = chosen.groups;
  if (!chosen.best)
    chosen.best = recognize_detail::recognize_union_detail({&stroke, 1}, recognizer_);
  UnionRecognition& best = *chosen.best;
  // A lone stroke certified on its ink keeps being certified on it (tidy-up): Q is obtained
  // then only, before anything changes (when still being built, its errors refuse the stroke).
  const Recognition& won = best.recognition;
  const bool tidy_on_ink = best_groups.empty() && won.certificate.method == "ink" && snaps(won) &&
                           won.shape != ShapeClass::kDot;
  const InkPolygon* stroke_ink = tidy_on_ink ? recognize_detail::given_ink(stroke) : nullptr;

  GroupUpdate update;
  GroupedShape& shape = update.shape;
  shape.id = next_id_++;
  for (const std::size_t g : best_groups) {
    update.superseded.push_back(groups_[g].shape.id);
    shape.strokes.insert(shape.strokes.end(), groups_[g].shape.strokes.begin(),
                         groups_[g].shape.strokes.end());
  }
  shape.strokes.push_back(index);
  std::sort(shape.strokes.begin(), shape.strokes.end());
  std::sort(best_groups.begin(), best_groups.end());
  for (std::size_t k = best_groups.size(); k-- > 0;) {
    groups_.erase(groups_.begin() + static_cast<std::ptrdiff_t>(best_groups[k]));
  }
  const std::vector<const Recognition*> neighbours =
      neighbour_shapes(groups_, grouping_.max_strokes);
  shape.recognition = std::move(best.recognition);
  // A lone stroke recognized on its ink keeps being certified on it.
  const InkPolygon* ink = shape.strokes.size() == 1 && shape.recognition.certificate.method == "ink"
                              ? stroke_ink
                              : nullptr;
  shape.tidy =
      recognize_detail::tidy_up(shape.recognition, best.strokes, grouping_.tidy, neighbours, ink);
  update.replaced_strokes = shape.strokes;

  // Groups before a long pause can join no later stroke: they drop their samples.
  for (Entry& e : groups_) {
    if (!e.joinable || !new_run) continue;
    e.joinable = false;
    for (const std::size_t i : e.shape.strokes) forget_stroke(i);
  }
  if (!dot) { // a dot's group is never joined
    strokes_[index] = path_only(stroke);
    touches_[index] = touches.take_own();
  }
  ++added_;
  groups_.push_back({shape, stroke.samples.back().t, !dot});
  return update;
}

std::vector<GroupedShape> recognize_strokes(std::span<const StrokeInput> strokes,
                                            const GroupingConfig& grouping,
                                            const RecognizerConfig& recognizer) {
  StrokeGrouper grouper(grouping, recognizer);
  for (const StrokeInput& s : strokes) grouper.add(s);
  return grouper.shapes();
}

} // namespace penshape
