#pragma once
// Shamos–Hoey detection: does any pair of closed segments share a point it may not? A left-to-
// right sweep keeps the segments crossing the sweep line in vertical order and compares only
// neighbours in that order, so n segments cost O(n log n) exact-predicate calls (validation
// used to compare every pair whose x-ranges overlap: O(n²) on a comb). Internal to core.
//
// One sweep for every exact point type: the input's rationals with their doubles
// (FilteredPoint, validation and templates) and the fast engine's integer grid points (its
// certifiable regions). A point type P needs compare_lex(P, P) (lexicographic, exact),
// orientation(P, P, P) and segments_intersect (exact_predicates.hpp), found by argument-dependent
// lookup.
//
// Events are the endpoints in lexicographic (x, y) order, i.e. a sweep line tilted
// infinitesimally so vertical segments need no special case. At each event point: first every
// pair of segments ending or starting there is checked, then the ending ones leave the status
// (their two neighbours become adjacent and are checked), then the starting ones enter it (each
// checked against its two neighbours). Until the first forbidden contact the active segments do
// not cross, so their vertical order is well defined; placing a new segment compares it only
// with active ones, by orientation.
#include <algorithm>
#include <array>
#include <cstddef>
#include <memory_resource>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "geometry/exact_predicates.hpp"
#include "penshape/core/base.hpp"

namespace penshape::detail {

template <typename P>
struct SweepSegmentOf {
  P a;
  P b; // a == b is allowed (a point), though validation never passes one
};
using SweepSegment = SweepSegmentOf<FilteredPoint>;

using Contact = std::pair<std::size_t, std::size_t>;

namespace sweep_impl {

// Thrown from inside the status comparator when placing a segment already proves a contact.
struct Found {
  Contact pair;
};

template <typename P>
struct Oriented {
  P left; // the lexicographically smaller endpoint
  P right;
};

// A segment's start or end, with its point (sorting compares points held in place).
template <typename P>
struct Event {
  P at;
  std::size_t segment;
  bool starts;
};

// `adjacent(i, j)`: segments i and j are neighbours along a ring and may share their common
// endpoint (and nothing else). Every other pair may share no point at all.
template <typename P, typename Adjacent>
class Sweep {
 public:
  Sweep(const std::vector<SweepSegmentOf<P>>& segments, const Adjacent& adjacent)
      : adjacent_(adjacent), status_(Below{this}, &pool_) {
    oriented_.reserve(segments.size());
    for (const SweepSegmentOf<P>& s : segments) {
      const bool forward = compare_lex(s.a, s.b) < 0;
      oriented_.push_back(forward ? Oriented<P>{s.a, s.b} : Oriented<P>{s.b, s.a});
    }
    where_.resize(segments.size());
    active_.assign(segments.size(), 0);
  }

  // Closed segments i and j share a point they may not.
  [[nodiscard]] bool forbidden(std::size_t i, std::size_t j) const {
    const Oriented<P>& s = oriented_[i];
    const Oriented<P>& t = oriented_[j];
    if (adjacent_(i, j)) {
      if (const auto shared = shared_endpoint(s, t)) {
        // Neighbours meet only at their common vertex unless they fold back onto each other.
        const auto& [c, a, b] = *shared;
        if (orientation(c, a, b) != 0) return false;
        return on_collinear_segment(exact_coordinates(c), exact_coordinates(a),
                                    exact_coordinates(b)) ||
               on_collinear_segment(exact_coordinates(c), exact_coordinates(b),
                                    exact_coordinates(a));
      }
    }
    return segments_intersect(s.left, s.right, t.left, t.right);
  }

  void check(std::size_t i, std::size_t j) const {
    if (i != j && forbidden(i, j)) throw Found{{std::min(i, j), std::max(i, j)}};
  }

  [[nodiscard]] bool active(std::size_t i) const { return active_[i] != 0; }

  void leave(std::size_t i) {
    active_[i] = 0;
    const auto it = where_[i];
    const auto next = std::next(it);
    if (it != status_.begin() && next != status_.end()) check(*std::prev(it), *next);
    status_.erase(it);
  }

  void enter(std::size_t i) {
    entering_ = i;
    const auto [it, inserted] = status_.insert(i);
    entering_ = kNone;
    where_[i] = it;
    active_[i] = 1;
    if (it != status_.begin()) check(*std::prev(it), i);
    if (const auto next = std::next(it); next != status_.end()) check(i, *next);
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  // The common endpoint c of two segments, with their other endpoints a (of s) and b (of t).
  static std::optional<std::array<P, 3>> shared_endpoint(const Oriented<P>& s,
                                                         const Oriented<P>& t) {
    for (const auto& [c, a] : {std::pair{s.left, s.right}, std::pair{s.right, s.left}}) {
      if (compare_lex(c, t.left) == 0) return std::array<P, 3>{c, a, t.right};
      if (compare_lex(c, t.right) == 0) return std::array<P, 3>{c, a, t.left};
    }
    return std::nullopt;
  }

  // Where the entering segment s lies against the active segment t, at s's left endpoint p:
  // +1 above, -1 below. A tie means p lies on t, or both leave p along one line: a contact.
  [[nodiscard]] int side(std::size_t t, std::size_t s) const {
    const Oriented<P>& ts = oriented_[t];
    const Oriented<P>& ss = oriented_[s];
    const int o = compare_lex(ts.left, ss.left) == 0 ? orientation(ss.left, ts.right, ss.right)
                                                     : orientation(ts.left, ts.right, ss.left);
    if (o == 0) throw Found{{std::min(s, t), std::max(s, t)}};
    return o;
  }

  // The status order, bottom to top. std::set compares only the entering segment with active
  // ones, so the comparator only has to place that one.
  struct Below {
    const Sweep* sweep;
    bool operator()(std::size_t a, std::size_t b) const {
      if (a == b) return false;
      if (a == sweep->entering_) return sweep->side(b, a) < 0;
      return sweep->side(a, b) > 0;
    }
  };

  using Status = std::pmr::set<std::size_t, Below>;

  const Adjacent& adjacent_;
  std::vector<Oriented<P>> oriented_;
  // The status' nodes come from one growing buffer, freed with the sweep (n small nodes).
  std::pmr::monotonic_buffer_resource pool_;
  Status status_;
  std::vector<typename Status::iterator> where_;
  std::vector<char> active_;
  std::size_t entering_ = kNone;
};

// The events (each segment's start and end) in lexicographic order of their points.
template <typename P>
std::vector<Event<P>> events_of(const std::vector<SweepSegmentOf<P>>& segments) {
  std::vector<Event<P>> events;
  events.reserve(2 * segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const bool forward = compare_lex(segments[i].a, segments[i].b) < 0;
    events.push_back({segments[i].a, i, forward});
    events.push_back({segments[i].b, i, !forward});
  }
  std::sort(events.begin(), events.end(),
            [](const Event<P>& e, const Event<P>& f) { return compare_lex(e.at, f.at) < 0; });
  return events;
}

// One event point: the segments meeting there, then leaving, then entering.
template <typename P, typename Adjacent>
void visit(Sweep<P, Adjacent>& sweep, const std::vector<Event<P>>& events, std::size_t begin,
           std::size_t end) {
  // Segments meeting at this point: valid input has two, the neighbours of one vertex.
  for (std::size_t i = begin; i < end; ++i) {
    for (std::size_t j = i + 1; j < end; ++j) sweep.check(events[i].segment, events[j].segment);
  }
  for (std::size_t i = begin; i < end; ++i) {
    if (!events[i].starts && sweep.active(events[i].segment)) sweep.leave(events[i].segment);
  }
  for (std::size_t i = begin; i < end; ++i) {
    if (events[i].starts) sweep.enter(events[i].segment);
  }
  // A zero-length segment (not valid input, but not a crash either) enters and leaves here.
  for (std::size_t i = begin; i < end; ++i) {
    if (!events[i].starts && sweep.active(events[i].segment)) sweep.leave(events[i].segment);
  }
}

} // namespace sweep_impl

// A pair (i < j) that shares a forbidden point, or nullopt when there is none. `adjacent(i, j)`
// says that segments i and j are neighbours along a ring: they may share their common endpoint
// (and nothing else); every other pair may share no point at all. cancel is polled every 256
// event points (throws Cancelled).
template <typename P, typename Adjacent>
std::optional<Contact> find_forbidden_contact(const std::vector<SweepSegmentOf<P>>& segments,
                                              const Adjacent& adjacent,
                                              const CancelHook& cancel = {}) {
  const std::vector<sweep_impl::Event<P>> events = sweep_impl::events_of(segments);
  sweep_impl::Sweep<P, Adjacent> sweep(segments, adjacent);
  try {
    std::size_t begin = 0;
    std::size_t groups = 0;
    while (begin < events.size()) {
      if (cancel && ++groups % 256 == 0 && cancel()) throw Cancelled();
      std::size_t end = begin + 1;
      while (end < events.size() && compare_lex(events[begin].at, events[end].at) == 0) ++end;
      sweep_impl::visit(sweep, events, begin, end);
      begin = end;
    }
  } catch (const sweep_impl::Found& found) {
    return found.pair;
  }
  return std::nullopt;
}

} // namespace penshape::detail
