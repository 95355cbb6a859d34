#pragma once
// Random deconstruction inputs with features at and below the fast engine's grid scale (issue
// 22): separate slivers 1e-7..1e-3 thick, needles touching and not touching a body, thin
// near-degenerate and twisted rings, thin holes, collinear runs, ties at the ε-band, and convex
// slivers alone (the convex path). Fixed seeds: case k is the same on every machine
// (std::mt19937_64 is specified exactly; no std distribution is used). Coordinates are doubles
// taken as exact rationals; a case may be invalid (callers validate and skip it).
#include <cstdint>
#include <string>

#include "penshape/core/deconstruct.hpp"

namespace penshape::test {

struct SoundnessCase {
  PolygonSet q;
  DeconstructParams params; // engine: fast (the default)
  std::string kind;         // what the generator built, for messages
};

// The case for this seed (any value).
SoundnessCase make_soundness_case(std::uint64_t seed);

// The kinds the generator cycles through (seed % kind_count picks one).
int soundness_kind_count();

} // namespace penshape::test
