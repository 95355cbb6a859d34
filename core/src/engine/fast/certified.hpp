#pragma once
// The fast engine's certified predicates: every comparison that decides a YES or NO certificate
// goes through this file (README.md, "What is certified and how"). Doubles propose candidates
// elsewhere; here each predicate is evaluated with interval arithmetic (CGAL::Interval_nt,
// directed rounding, through geometry/distance_kernel.hpp) and, when the interval cannot decide,
// with exact rationals. Points are doubles or integers, thresholds are doubles: all exactly
// representable as rationals, so the exact fallback answers the very question asked.
#include <CGAL/FPU.h>

#include <cstdint>
#if defined(__x86_64__) && defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "int_geometry.hpp"

namespace penshape::fast {

// Rounding towards +infinity, what CGAL::Interval_nt<false> needs, for this scope. On x86-64
// every double operation is SSE, so one MXCSR write does it (CGAL's Protect_FPU_rounding goes
// through fesetround, which also sets the unused x87 unit and costs several times more; the
// certificates switch modes hundreds of thousands of times). Elsewhere: CGAL's.
#if defined(__x86_64__) && defined(__SSE2__)
class UpwardRounding {
 public:
  UpwardRounding() : saved_(_mm_getcsr()) {
    // CGAL's interval sqrt switches both units through fesetround: keep the x87 word too.
    __asm__ volatile("fnstcw %0" : "=m"(saved_x87_));
    _mm_setcsr((saved_ & ~static_cast<unsigned>(_MM_ROUND_MASK)) | _MM_ROUND_UP);
  }
  ~UpwardRounding() {
    _mm_setcsr(saved_);
    // Reloading the x87 word is slow (fldcw): only when something in the scope changed it.
    unsigned short now = 0;
    __asm__ volatile("fnstcw %0" : "=m"(now));
    if (now != saved_x87_) __asm__ volatile("fldcw %0" : : "m"(saved_x87_));
  }
  UpwardRounding(const UpwardRounding&) = delete;
  UpwardRounding& operator=(const UpwardRounding&) = delete;

 private:
  unsigned saved_;
  unsigned short saved_x87_ = 0;
};
#else
using UpwardRounding = CGAL::Protect_FPU_rounding<true>;
#endif

// How many predicates (in this thread) needed the exact fallback so far: for tests that must
// exercise it, and for the README's account of how often intervals decide.
[[nodiscard]] std::uint64_t exact_fallbacks();

// The point p + t (q - p) for double p, q, t: a point of the segment [p, q] when t is in
// [0, 1], exact as a rational (no rounding happens in its definition).
struct OnPiece {
  DPt p;
  DPt q;
  double t = 0.0;
};
inline OnPiece at_point(DPt p) { return {p, p, 0.0}; }
inline OnPiece at_point(IPt p) { return at_point(to_d(p)); }

// sign(d(y, [a, b]) - T) for T >= 0, certified (0 only when equal).
[[nodiscard]] int compare_distance(const OnPiece& y, IPt a, IPt b, double threshold);
// sign(|y - z| - T) for T >= 0, certified.
[[nodiscard]] int compare_point_distance(const OnPiece& y, const OnPiece& z, double threshold);

inline bool closer_than(const OnPiece& y, IPt a, IPt b, double threshold) {
  return threshold > 0.0 && compare_distance(y, a, b, threshold) < 0;
}
inline bool farther_than(const OnPiece& y, IPt a, IPt b, double threshold) {
  return compare_distance(y, a, b, threshold) > 0;
}

// Whether d([y0, y1], [a, b]) > T is proven: the segments are strictly separated by the line of
// one of them and all four endpoint-to-segment distances exceed T (false: not shown).
[[nodiscard]] bool segments_farther_than(const OnPiece& y0, const OnPiece& y1, IPt a, IPt b,
                                         double threshold);

// A length in grid units known by bounds lo <= value <= hi (doubles, outward rounded).
struct Bounds {
  double lo = 0.0;
  double hi = 0.0;
};

// A box that surely contains the points y0 and y1.
struct Box {
  double lo_x, lo_y, hi_x, hi_y;
};
[[nodiscard]] Box enclosing_box(const OnPiece& y0, const OnPiece& y1);

// Outward-rounded arithmetic for deriving bounds (each result encloses the exact value).
[[nodiscard]] double add_up(double a, double b);
[[nodiscard]] double sub_down(double a, double b); // a lower bound on a - b

class SegmentIndex;

// Every edge of the index is proven farther than T from the segment [y0, y1]
// (segments_farther_than edge by edge, under one rounding-mode switch).
[[nodiscard]] bool piece_farther_than(const SegmentIndex& index, const OnPiece& y0,
                                      const OnPiece& y1, double threshold);
// Every edge of the index is proven farther than T from y (an edge whose box is proven farther
// along an axis is skipped by that argument alone).
[[nodiscard]] bool all_edges_farther(const SegmentIndex& index, const OnPiece& y, double threshold);
// Some edge of the index is proven closer than T to y (doubles propose the nearest edge). With
// a hint, the edge *hint is tried first, and *hint is set to the edge that proved it (kept when
// none did).
[[nodiscard]] bool some_edge_closer(const SegmentIndex& index, const OnPiece& y, double threshold,
                                    std::size_t* hint = nullptr);

} // namespace penshape::fast
