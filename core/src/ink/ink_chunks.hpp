#pragma once
// The ink polygon in chunks (internal to core/src/ink): a stroke's samples are cut into chunks of
// kChunkSegments segments that share their end samples, each chunk becomes Clipper pieces on its
// own, and Q is the one final union of all pieces. The one-shot ink_polygon() and InkBuilder
// (which builds the chunks while the pen is down) both go through here, so they give the same Q
// bit for bit.
#include <clipper.hpp>

#include <cstddef>
#include <limits>
#include <vector>

#include "ink_union.hpp"
#include "penshape/core/base.hpp"
#include "penshape/core/ink.hpp"

namespace penshape::ink_detail {

// Segments per chunk: a pen-up has at most this many segments left to offset.
constexpr std::size_t kChunkSegments = kInkChunkSegments;

// The first sample of chunk c is c·kChunkSegments; its last is the next chunk's first (or the
// stroke's last sample).
inline std::size_t chunk_count(std::size_t samples) {
  return samples <= 1 ? samples : (samples - 2) / kChunkSegments + 1;
}

// The largest radius and coordinate magnitude of the samples (mm).
struct Reach {
  double r_min = std::numeric_limits<double>::infinity();
  double r_max = 0;
  double extent = 0;
};

// The grid, the disk polygon and the bound for each kind of piece (ink.hpp's error budget).
struct Plan {
  double grid = 0;
  std::size_t k = 0;
  double tau = 0;
  double arc_tolerance = 0;
  double hull_bound = 0;
  double offset_bound = 0;
  double final_union = 0; // the final union's share of either bound (rounding, doubles, sweep)
  double min_radius = 0;  // mm: smaller disks are drawn this large
};

// The options' maximal error, after checking the options and the sample count (InvalidInput).
double checked_max_error(const InkOptions& options, std::size_t total);
// The strokes' reach, after checking each sample (InvalidInput); one stroke's alike.
Reach checked_reach(const std::vector<std::vector<InkSample>>& strokes);
Reach checked_reach(const std::vector<InkSample>& samples);
// Widens `reach` (of samples [0, from), checked) by samples [from, end) after checking them, so
// that the reach of a growing stroke costs each sample once; the same reach as checked_reach.
void widen_checked_reach(const std::vector<InkSample>& samples, std::size_t from, Reach& reach);
Plan plan_for(double max_error, const Reach& reach);

// One chunk's Clipper pieces, with what they depend on in the plan.
struct ChunkPieces {
  ClipperLib::Paths paths;
  bool offset = false; // Clipper's offset (one radius), else hulls of disks
  double grid = 0;     // the plan's grid they were rounded to
  std::size_t k = 0;   // the disk polygon's vertex count (hulls only)
  double pinch = 1.0;  // clipper_pinch_factor of the paths
};

// The pieces of samples [first, first + count) (count >= 1) under `plan`.
ChunkPieces build_chunk(const InkSample* first, std::size_t count, const Plan& plan);

// True when `pieces` were built under a plan that gives the same pieces as `plan`.
bool same_pieces(const ChunkPieces& pieces, const Plan& plan);

// v grid units in mm, exactly (grid a power of two, as plan_for chooses it).
Rational on_grid(ClipperLib::cInt v, double grid);

// Q of the chunks' pieces, in order: the final union and the bound.
InkPolygon assemble(const std::vector<const ChunkPieces*>& chunks, const Plan& plan);
// The same, with `fed` already given the pieces of chunks[0, fed_chunks) in order (ink_union.hpp
// FedUnion): the rest are added and the union executed (once: `fed` is spent).
InkPolygon assemble(const std::vector<const ChunkPieces*>& chunks, const Plan& plan, FedUnion& fed,
                    std::size_t fed_chunks);

} // namespace penshape::ink_detail
