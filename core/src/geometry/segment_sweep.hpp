#pragma once
// Shamos–Hoey detection: does any pair of closed segments share a point it may not? A left-to-
// right sweep keeps the segments crossing the sweep line in vertical order and compares only
// neighbours in that order, so n segments cost O(n log n) exact-predicate calls (validation
// used to compare every pair whose x-ranges overlap: O(n²) on a comb). Internal to core.
#include <cstddef>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/exact_predicates.hpp"
#include "penshape/core/base.hpp"

namespace penshape::detail {

struct SweepSegment {
  FilteredPoint a;
  FilteredPoint b; // a == b is allowed (a point), though validation never passes one
};

// Whether segments i and j are neighbours along a ring: they may share their common endpoint
// (and nothing else). Every other pair may share no point at all.
using AdjacentSegments = std::function<bool(std::size_t, std::size_t)>;

// A pair (i < j) that shares a forbidden point, or nullopt when there is none. cancel is polled
// every 256 events (throws Cancelled).
std::optional<std::pair<std::size_t, std::size_t>> find_forbidden_contact(
    const std::vector<SweepSegment>& segments, const AdjacentSegments& adjacent,
    const CancelHook& cancel = {});

} // namespace penshape::detail
