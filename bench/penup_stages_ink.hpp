#pragma once
// The pen-up's ink polygon Q split for penup_stages.hpp: Q's final union alone (Clipper, every
// chunk's pieces), and the incremental alternative the daemon does not use, the union of the
// closed chunks (which could be kept while the pen is down) with the last chunk's pieces. That
// alternative is timed and compared with Q exactly: Clipper rounds each union's intersection
// points to its grid and takes its sweep's decisions on rounded x (core/src/ink/ink_union.hpp),
// so a union of unions is not the one union of the pieces. A vertex of one that does not lie on
// the other's boundary (exact int128 tests) proves that the two sets differ.
#include <clipper.hpp>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "ink/ink_chunks.hpp"
#include "ink/ink_union.hpp"
#include "penshape/core/ink.hpp"
#include "penup_stages_time.hpp"

namespace penshape::bench {

// How Q's final union compares with the closed chunks' union joined with the last chunk.
struct ChainComparison {
  bool same_vertices = true; // the same vertices, as sorted lists
  bool proven_different = false;
};

// True when p lies on a boundary edge of `paths` (exact: collinear and within the edge's box).
inline bool on_boundary(const ClipperLib::IntPoint& p, const ClipperLib::Paths& paths) {
  __extension__ using Int128 = __int128;
  for (const ClipperLib::Path& path : paths) {
    for (std::size_t i = 0; i < path.size(); ++i) {
      const ClipperLib::IntPoint& a = path[i];
      const ClipperLib::IntPoint& b = path[(i + 1) % path.size()];
      const Int128 cross = static_cast<Int128>(b.X - a.X) * (p.Y - a.Y) -
                           static_cast<Int128>(b.Y - a.Y) * (p.X - a.X);
      if (cross == 0 && std::min(a.X, b.X) <= p.X && p.X <= std::max(a.X, b.X) &&
          std::min(a.Y, b.Y) <= p.Y && p.Y <= std::max(a.Y, b.Y)) {
        return true;
      }
    }
  }
  return false;
}

inline std::vector<std::pair<ClipperLib::cInt, ClipperLib::cInt>> sorted_vertices(
    const ClipperLib::Paths& paths) {
  std::vector<std::pair<ClipperLib::cInt, ClipperLib::cInt>> out;
  for (const ClipperLib::Path& path : paths) {
    for (const ClipperLib::IntPoint& p : path) out.emplace_back(p.X, p.Y);
  }
  std::sort(out.begin(), out.end());
  return out;
}

inline ChainComparison compare_unions(const ClipperLib::Paths& a, const ClipperLib::Paths& b) {
  ChainComparison out;
  out.same_vertices = sorted_vertices(a) == sorted_vertices(b);
  const auto outside = [](const ClipperLib::Paths& from, const ClipperLib::Paths& other) {
    return std::any_of(from.begin(), from.end(), [&](const ClipperLib::Path& path) {
      return std::any_of(path.begin(), path.end(),
                         [&](const ClipperLib::IntPoint& p) { return !on_boundary(p, other); });
    });
  };
  out.proven_different = !out.same_vertices && (outside(a, b) || outside(b, a));
  return out;
}

// Q's final union and the closed-chunks alternative, timed on one stroke's samples.
struct InkUnionTimes {
  StepTime final_union, chain_union;
  std::size_t strokes = 0, other_vertices = 0, other_sets = 0;

  void time(const std::vector<InkSample>& samples, const InkOptions& options) {
    namespace ink = ink_detail;
    const ink::Plan plan =
        ink::plan_for(ink::checked_max_error(options, samples.size()), ink::checked_reach(samples));
    const std::size_t n = ink::chunk_count(samples.size());
    if (n < 2) return;
    ClipperLib::Paths all, closed, last;
    for (std::size_t c = 0; c < n; ++c) {
      const std::size_t first = c * ink::kChunkSegments;
      const std::size_t count = std::min(ink::kChunkSegments + 1, samples.size() - first);
      const ink::ChunkPieces chunk = ink::build_chunk(samples.data() + first, count, plan);
      all.insert(all.end(), chunk.paths.begin(), chunk.paths.end());
      ClipperLib::Paths& part = c + 1 < n ? closed : last;
      part.insert(part.end(), chunk.paths.begin(), chunk.paths.end());
    }
    ClipperLib::Paths one_shot, chain;
    ClipperLib::PolyTree tree;
    final_union.time([&] { (void)ink::clipper_union(all, tree); });
    ClipperLib::PolyTreeToPaths(tree, one_shot);
    (void)ink::clipper_union(closed, tree); // kept while the pen is down: untimed
    ClipperLib::PolyTreeToPaths(tree, closed);
    closed.insert(closed.end(), last.begin(), last.end());
    chain_union.time([&] { (void)ink::clipper_union(closed, tree); });
    ClipperLib::PolyTreeToPaths(tree, chain);
    const ChainComparison c = compare_unions(one_shot, chain);
    ++strokes;
    other_vertices += c.same_vertices ? 0 : 1;
    other_sets += c.proven_different ? 1 : 0;
  }
};

} // namespace penshape::bench
