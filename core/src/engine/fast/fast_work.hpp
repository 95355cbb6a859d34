#pragma once
// What one decision of the fast engine builds before its chains and certificates, kept for the
// solution simplifier of the same call (deconstruct_simplified): the grid frame, Q̃, its index
// and the certified Q_s, and what the YES check's (A1) walk proved about Q_s alone. Rebuilding
// them cost about a third of the simplifier's time on 200,000 vertices (issue 26).
#include <optional>

#include "grid_frame.hpp"
#include "level_set_check.hpp"
#include "segment_index.hpp"
#include "yes_certificate.hpp"

namespace penshape::detail {

struct FastWork {
  // Built in this order from the oriented Q and the parameters (decide_fast).
  fast::GridFrame frame;
  fast::GridInput grid;
  fast::SegmentIndex q_index;             // Q̃ (cell eps / 2)
  fast::CertifiedInput input;             // Q_s at delta / 4 (cell eps / 2)
  double input_tolerance = 0.0;           // delta / 4 in grid units: what `input` was asked for
  std::optional<fast::LevelSetMemo> memo; // (A1)'s deep pieces of Q_s, when YES was tried
};

} // namespace penshape::detail
