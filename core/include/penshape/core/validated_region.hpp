#pragma once
// A region that validate_region accepted, as a type: a caller that validated Q once (to report
// its own errors, e.g. the CLI naming the file) hands it to deconstruct() without validating the
// region again (issue 26: validation was 0.2 s of the CLI's 200,000-vertex call, twice).
#include <cstddef>
#include <utility>

#include "penshape/core/deconstruct.hpp"

namespace penshape {

class ValidatedRegion {
 public:
  // validate_region(q, max_vertices, cancel): throws InvalidInput (or Cancelled) as it does.
  static ValidatedRegion validate(PolygonSet q, std::size_t max_vertices = 200'000,
                                  const CancelHook& cancel = {});

  [[nodiscard]] const PolygonSet& region() const { return q_; }
  // The region itself, moved out (the token is then spent: its region is empty).
  [[nodiscard]] PolygonSet release() && { return std::move(q_); }

 private:
  explicit ValidatedRegion(PolygonSet q) : q_(std::move(q)) {}
  PolygonSet q_;
};

// deconstruct() on a region already validated: the parameters are validated (and the vertex
// count against limits.max_input_vertices, with validate_region's message), the region's
// geometry is not again. `elapsed` then leaves out the region's validation.
DeconstructResult deconstruct(const ValidatedRegion& q, const DeconstructParams& params,
                              const CancelHook& cancel = {}, const DeconstructLimits& limits = {});

} // namespace penshape
