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
// Two layouts of the same sweep: closed rings (`find_ring_contact`: one event per vertex, where
// the vertex's two edges start or end; what validation and the engines use) and free segments
// with a neighbour test (`find_forbidden_contact`: one event per segment end).
//
// Events are points in lexicographic (x, y) order, i.e. a sweep line tilted infinitesimally so
// vertical segments need no special case. At each event point: first every pair of segments
// ending or starting there is checked, then the ending ones leave the status (their two
// neighbours become adjacent and are checked), then the starting ones enter it (each checked
// against its two neighbours). Until the first forbidden contact the active segments do not
// cross, so their vertical order is well defined; placing a new segment compares it only with
// active ones, by orientation.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <optional>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "geometry/exact_predicates.hpp"
#include "geometry/node_recycler.hpp"
#include "penshape/core/base.hpp"

namespace penshape::detail {

template <typename P>
struct SweepSegmentOf {
  P a;
  P b; // a == b is allowed (a point), though validation never passes one
};
using SweepSegment = SweepSegmentOf<FilteredPoint>;

using Contact = std::pair<std::size_t, std::size_t>;

// Edge `index` of ring `ring`: from its vertex index to the next one (the last to the first).
struct RingEdge {
  std::size_t ring = 0;
  std::size_t index = 0;
};

namespace sweep_impl {

// Thrown from inside the status comparator when placing a segment already proves a contact.
struct Found {
  Contact pair;
};

// A point to sort, copied beside the layout's number for it (sorting reads no other memory).
template <typename P>
struct Key {
  P at;
  std::size_t id;
};

// A segment's end met at an event point: which segment, and whether it starts there.
struct Entry {
  std::size_t segment;
  bool starts;
};

// Free segments and a neighbour test: point 2i is segment i's end a, point 2i + 1 its end b.
template <typename P, typename Adjacent>
class SegmentLayout {
 public:
  using Point = P;
  SegmentLayout(const std::vector<SweepSegmentOf<P>>& segments, const Adjacent& adjacent)
      : segments_(segments), adjacent_(adjacent) {}
  [[nodiscard]] std::size_t segment_count() const { return segments_.size(); }
  [[nodiscard]] const P& a(std::size_t i) const { return segments_[i].a; }
  [[nodiscard]] const P& b(std::size_t i) const { return segments_[i].b; }
  [[nodiscard]] bool adjacent(std::size_t i, std::size_t j) const { return adjacent_(i, j); }
  [[nodiscard]] std::vector<Key<P>> keys() const {
    std::vector<Key<P>> out;
    out.reserve(2 * segments_.size());
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      out.push_back({segments_[i].a, 2 * i});
      out.push_back({segments_[i].b, 2 * i + 1});
    }
    return out;
  }
  // f(segment, is_end_a) for the segment end that point `id` is.
  template <typename F>
  void ends_at(std::size_t id, F&& f) const {
    f(id / 2, id % 2 == 0);
  }

 private:
  const std::vector<SweepSegmentOf<P>>& segments_;
  const Adjacent& adjacent_;
};

// Closed rings numbered as one sequence: edge g joins vertex g to the next vertex of its ring,
// so vertex g is the end a of edge g and the end b of the edge before it.
template <typename P>
class RingLayout {
 public:
  using Point = P;
  explicit RingLayout(const std::vector<std::span<const P>>& rings) : rings_(rings) {
    begin_.reserve(rings.size() + 1);
    begin_.push_back(0);
    for (const auto& ring : rings) begin_.push_back(begin_.back() + ring.size());
    ring_of_.resize(begin_.back());
    for (std::size_t r = 0; r < rings.size(); ++r) {
      std::fill(ring_of_.begin() + static_cast<std::ptrdiff_t>(begin_[r]),
                ring_of_.begin() + static_cast<std::ptrdiff_t>(begin_[r + 1]), r);
    }
  }
  [[nodiscard]] std::size_t segment_count() const { return begin_.back(); }
  [[nodiscard]] const P& a(std::size_t g) const {
    const std::size_t r = ring_of_[g];
    return rings_[r][g - begin_[r]];
  }
  [[nodiscard]] const P& b(std::size_t g) const { return a(next(g)); }
  [[nodiscard]] bool adjacent(std::size_t i, std::size_t j) const {
    return next(i) == j || next(j) == i;
  }
  [[nodiscard]] std::vector<Key<P>> keys() const {
    std::vector<Key<P>> out;
    out.reserve(segment_count());
    for (std::size_t r = 0; r < rings_.size(); ++r) {
      for (std::size_t i = 0; i < rings_[r].size(); ++i)
        out.push_back({rings_[r][i], begin_[r] + i});
    }
    return out;
  }
  template <typename F>
  void ends_at(std::size_t g, F&& f) const {
    f(g, true);
    f(previous(g), false);
  }
  [[nodiscard]] RingEdge locate(std::size_t g) const {
    const std::size_t r = ring_of_[g];
    return {r, g - begin_[r]};
  }

 private:
  [[nodiscard]] std::size_t next(std::size_t g) const {
    const std::size_t r = ring_of_[g];
    return g + 1 < begin_[r + 1] ? g + 1 : begin_[r];
  }
  [[nodiscard]] std::size_t previous(std::size_t g) const {
    const std::size_t r = ring_of_[g];
    return g > begin_[r] ? g - 1 : begin_[r + 1] - 1;
  }

  const std::vector<std::span<const P>>& rings_;
  std::vector<std::size_t> begin_; // first edge of each ring, and the total
  std::vector<std::size_t> ring_of_;
};

// The status and the pair checks of one sweep over a layout's segments.
template <typename Layout>
class Sweep {
  using P = typename Layout::Point;

 public:
  explicit Sweep(const Layout& layout) : layout_(layout), status_(Below{this}, &pool_) {
    const std::size_t n = layout.segment_count();
    state_.resize(n);
    ends_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const P& a = layout.a(i);
      const P& b = layout.b(i);
      const bool forward = compare_lex(a, b) < 0;
      state_[i] = forward ? kForward : 0;
      ends_.push_back(forward ? Ends{&a, &b} : Ends{&b, &a});
    }
    where_.resize(n);
  }

  // Closed segments i and j share a point they may not.
  [[nodiscard]] bool forbidden(std::size_t i, std::size_t j) const {
    if (layout_.adjacent(i, j)) {
      if (const auto shared = shared_endpoint(i, j)) {
        // Neighbours meet only at their common vertex unless they fold back onto each other.
        const auto& [c, a, b] = *shared;
        if (orientation(*c, *a, *b) != 0) return false;
        return on_collinear_segment(exact_coordinates(*c), exact_coordinates(*a),
                                    exact_coordinates(*b)) ||
               on_collinear_segment(exact_coordinates(*c), exact_coordinates(*b),
                                    exact_coordinates(*a));
      }
    }
    return segments_intersect(left(i), right(i), left(j), right(j));
  }

  void check(std::size_t i, std::size_t j) const {
    if (i != j && forbidden(i, j)) throw Found{{std::min(i, j), std::max(i, j)}};
  }

  // Whether segment i starts at its end a (or b) : the end a is its left end.
  [[nodiscard]] bool starts_at(std::size_t i, bool end_a) const {
    return end_a == ((state_[i] & kForward) != 0);
  }

  [[nodiscard]] bool active(std::size_t i) const { return (state_[i] & kActive) != 0; }

  // Removes i; where it was is kept as a hint for a segment entering at the same point.
  void leave(std::size_t i) {
    state_[i] &= static_cast<std::uint8_t>(~kActive);
    const auto it = where_[i];
    const auto next = std::next(it);
    if (it != status_.begin() && next != status_.end()) check(*std::prev(it), *next);
    hint_ = status_.erase(it);
  }

  // The next event point starts without a hint.
  void forget_hint() { hint_.reset(); }

  // Inserts i. A hint is only tried first: std::set compares i with the hint's neighbours and
  // searches the whole status when they do not enclose it, so the order is the same either
  // way, in two comparisons where one edge of a ring ends and the next starts (it takes the
  // ending one's place) instead of a search.
  void enter(std::size_t i) {
    entering_ = i;
    const auto it = hint_ ? status_.insert(*hint_, i) : status_.insert(i).first;
    entering_ = kNone;
    hint_ = it; // a second edge starting here lies next to this one
    where_[i] = it;
    state_[i] |= kActive;
    if (it != status_.begin()) check(*std::prev(it), i);
    if (const auto next = std::next(it); next != status_.end()) check(i, *next);
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  static constexpr std::uint8_t kForward = 1; // end a is the lexicographically smaller end
  static constexpr std::uint8_t kActive = 2;

  // A segment's ends in sweep order (the status comparator reads them most).
  struct Ends {
    const P* left;
    const P* right;
  };

  [[nodiscard]] const P& left(std::size_t i) const { return *ends_[i].left; }
  [[nodiscard]] const P& right(std::size_t i) const { return *ends_[i].right; }

  // The common endpoint c of segments i and j, with their other endpoints a (of i), b (of j).
  [[nodiscard]] std::optional<std::array<const P*, 3>> shared_endpoint(std::size_t i,
                                                                       std::size_t j) const {
    const P& sl = left(i);
    const P& sr = right(i);
    const P& tl = left(j);
    const P& tr = right(j);
    for (const auto& [c, a] : {std::pair{&sl, &sr}, std::pair{&sr, &sl}}) {
      if (compare_lex(*c, tl) == 0) return std::array<const P*, 3>{c, a, &tr};
      if (compare_lex(*c, tr) == 0) return std::array<const P*, 3>{c, a, &tl};
    }
    return std::nullopt;
  }

  // Where the entering segment s lies against the active segment t, at s's left endpoint p:
  // +1 above, -1 below. A tie means p lies on t, or both leave p along one line: a contact.
  [[nodiscard]] int side(std::size_t t, std::size_t s) const {
    const P& tl = left(t);
    const P& sl = left(s);
    const int o = compare_lex(tl, sl) == 0 ? orientation(sl, right(t), right(s))
                                           : orientation(tl, right(t), sl);
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

  const Layout& layout_;
  std::vector<std::uint8_t> state_; // kForward, kActive
  std::vector<Ends> ends_;
  // The status' nodes are recycled (node_recycler.hpp): the status is small, so its nodes stay
  // in cache (a growing buffer took a fresh node for each of the n insertions).
  NodeRecycler pool_;
  Status status_;
  std::vector<typename Status::iterator> where_;
  std::optional<typename Status::const_iterator> hint_;
  std::size_t entering_ = kNone;
};

// One event point (keys [begin, end)): the segments meeting there, then leaving, then entering.
template <typename Layout>
void visit(Sweep<Layout>& sweep, const Layout& layout,
           const std::vector<Key<typename Layout::Point>>& keys, std::size_t begin, std::size_t end,
           std::vector<Entry>& entries) {
  entries.clear();
  for (std::size_t k = begin; k < end; ++k) {
    layout.ends_at(keys[k].id, [&](std::size_t segment, bool end_a) {
      entries.push_back({segment, sweep.starts_at(segment, end_a)});
    });
  }
  // Segments meeting at this point: valid input has two, the neighbours of one vertex.
  for (std::size_t i = 0; i < entries.size(); ++i) {
    for (std::size_t j = i + 1; j < entries.size(); ++j) {
      sweep.check(entries[i].segment, entries[j].segment);
    }
  }
  sweep.forget_hint();
  for (const Entry& e : entries) {
    if (!e.starts && sweep.active(e.segment)) sweep.leave(e.segment);
  }
  for (const Entry& e : entries) {
    if (e.starts) sweep.enter(e.segment);
  }
  // A zero-length segment (not valid input, but not a crash either) enters and leaves here.
  for (const Entry& e : entries) {
    if (!e.starts && sweep.active(e.segment)) sweep.leave(e.segment);
  }
}

// The sweep over a layout's points in lexicographic order; cancel polled every 256 points.
template <typename Layout>
std::optional<Contact> run(const Layout& layout, const CancelHook& cancel) {
  using P = typename Layout::Point;
  std::vector<Key<P>> keys = layout.keys();
  std::sort(keys.begin(), keys.end(),
            [](const Key<P>& e, const Key<P>& f) { return compare_lex(e.at, f.at) < 0; });
  Sweep<Layout> sweep(layout);
  std::vector<Entry> entries;
  try {
    std::size_t begin = 0;
    std::size_t groups = 0;
    while (begin < keys.size()) {
      if (cancel && ++groups % 256 == 0 && cancel()) throw Cancelled();
      std::size_t end = begin + 1;
      while (end < keys.size() && compare_lex(keys[begin].at, keys[end].at) == 0) ++end;
      visit(sweep, layout, keys, begin, end, entries);
      begin = end;
    }
  } catch (const Found& found) {
    return found.pair;
  }
  return std::nullopt;
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
  return sweep_impl::run(sweep_impl::SegmentLayout<P, Adjacent>(segments, adjacent), cancel);
}

// The same question for the edges of closed rings (ring k's vertices in order, the last joined
// to the first): two consecutive edges of a ring may share their common vertex (unless they
// fold back onto each other), no other two edges may share a point. Returns such a pair, the
// first one earlier in the rings' order, or nullopt. One event per vertex: half the events
// of the segment form, and each event reads its vertex's neighbours, which lie beside it.
template <typename P>
std::optional<std::pair<RingEdge, RingEdge>> find_ring_contact(
    const std::vector<std::span<const P>>& rings, const CancelHook& cancel = {}) {
  const sweep_impl::RingLayout<P> layout(rings);
  const auto contact = sweep_impl::run(layout, cancel);
  if (!contact) return std::nullopt;
  return std::pair{layout.locate(contact->first), layout.locate(contact->second)};
}

} // namespace penshape::detail
