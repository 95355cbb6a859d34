// Shamos–Hoey segment-contact detection (see segment_sweep.hpp). Events are the endpoints in
// lexicographic (x, y) order, i.e. a sweep line tilted infinitesimally so vertical segments
// need no special case. At each event point: first every pair of segments ending or starting
// there is checked, then the ending ones leave the status (their two neighbours become adjacent
// and are checked), then the starting ones enter it (each checked against its two neighbours).
// Until the first forbidden contact the active segments do not cross, so their vertical order
// is well defined; placing a new segment compares it only with active ones, by orientation.
#include "geometry/segment_sweep.hpp"

#include <algorithm>
#include <array>
#include <set>

namespace penshape::detail {
namespace {

using Contact = std::pair<std::size_t, std::size_t>;

// Thrown from inside the status comparator when placing a segment already proves a contact.
struct Found {
  Contact pair;
};

struct Oriented {
  FilteredPoint left; // the lexicographically smaller endpoint
  FilteredPoint right;
};

struct Event {
  FilteredPoint at;
  std::size_t segment;
  bool starts;
};

class Sweep {
 public:
  Sweep(const std::vector<SweepSegment>& segments, const AdjacentSegments& adjacent)
      : adjacent_(adjacent), status_(Below{this}) {
    oriented_.reserve(segments.size());
    for (const SweepSegment& s : segments) {
      const bool forward = compare_lex(s.a, s.b) < 0;
      oriented_.push_back(forward ? Oriented{s.a, s.b} : Oriented{s.b, s.a});
    }
    where_.resize(segments.size());
    active_.assign(segments.size(), 0);
  }

  // Closed segments i and j share a point they may not.
  bool forbidden(std::size_t i, std::size_t j) const {
    const Oriented& s = oriented_[i];
    const Oriented& t = oriented_[j];
    if (adjacent_ && adjacent_(i, j)) {
      const auto shared = shared_endpoint(s, t);
      if (shared) {
        // Neighbours meet only at their common vertex unless they fold back onto each other.
        const auto [c, a, b] = *shared;
        if (orientation(c, a, b) != 0) return false;
        return on_collinear_segment(*c.exact, *a.exact, *b.exact) ||
               on_collinear_segment(*c.exact, *b.exact, *a.exact);
      }
    }
    return segments_intersect(s.left, s.right, t.left, t.right);
  }

  void check(std::size_t i, std::size_t j) const {
    if (i != j && forbidden(i, j)) throw Found{{std::min(i, j), std::max(i, j)}};
  }

  bool active(std::size_t i) const { return active_[i] != 0; }

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
  static std::optional<std::array<FilteredPoint, 3>> shared_endpoint(const Oriented& s,
                                                                     const Oriented& t) {
    for (const auto& [c, a] : {std::pair{s.left, s.right}, std::pair{s.right, s.left}}) {
      if (compare_lex(c, t.left) == 0) return std::array{c, a, t.right};
      if (compare_lex(c, t.right) == 0) return std::array{c, a, t.left};
    }
    return std::nullopt;
  }

  // Where the entering segment s lies against the active segment t, at s's left endpoint p:
  // +1 above, -1 below. A tie means p lies on t, or both leave p along one line: a contact.
  int side(std::size_t t, std::size_t s) const {
    const Oriented& ts = oriented_[t];
    const Oriented& ss = oriented_[s];
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

  const AdjacentSegments& adjacent_;
  std::vector<Oriented> oriented_;
  std::set<std::size_t, Below> status_;
  std::vector<std::set<std::size_t, Below>::iterator> where_;
  std::vector<char> active_;
  std::size_t entering_ = kNone;
};

std::vector<Event> events_of(const std::vector<SweepSegment>& segments) {
  std::vector<Event> events;
  events.reserve(2 * segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const bool forward = compare_lex(segments[i].a, segments[i].b) < 0;
    events.push_back({segments[i].a, i, forward});
    events.push_back({segments[i].b, i, !forward});
  }
  std::sort(events.begin(), events.end(),
            [](const Event& e, const Event& f) { return compare_lex(e.at, f.at) < 0; });
  return events;
}

} // namespace

std::optional<Contact> find_forbidden_contact(const std::vector<SweepSegment>& segments,
                                              const AdjacentSegments& adjacent,
                                              const CancelHook& cancel) {
  const std::vector<Event> events = events_of(segments);
  Sweep sweep(segments, adjacent);
  try {
    std::size_t begin = 0;
    std::size_t groups = 0;
    while (begin < events.size()) {
      if (cancel && ++groups % 256 == 0 && cancel()) throw Cancelled();
      std::size_t end = begin + 1;
      while (end < events.size() && compare_lex(events[begin].at, events[end].at) == 0) ++end;
      // Segments meeting at this point: valid input has two, the neighbours of one vertex.
      for (std::size_t i = begin; i < end; ++i) {
        for (std::size_t j = i + 1; j < end; ++j) {
          sweep.check(events[i].segment, events[j].segment);
        }
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
      begin = end;
    }
  } catch (const Found& found) {
    return found.pair;
  }
  return std::nullopt;
}

} // namespace penshape::detail
