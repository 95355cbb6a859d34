#pragma once
// Twice the signed area of a closed ring (the shoelace sum), written once for every number type:
// rationals for the public PolygonSet (polygon_set.cpp), 64-bit integer points summed in 128 bits
// for the fast engine's grid. Its sign is the ring's orientation. Internal to core.
#include <cstddef>
#include <type_traits>

namespace penshape::detail {

// v as Acc: the value itself when it already is one (no copy of a rational), else converted.
template <typename Acc, typename T>
decltype(auto) as_accumulator(const T& v) {
  if constexpr (std::is_same_v<Acc, T>) {
    return (v);
  } else {
    return static_cast<Acc>(v);
  }
}

// Sum of x_i y_{i+1} - y_i x_{i+1} over the ring's edges (the last vertex joins the first), in
// Acc: exact when Acc holds every partial sum (Rational always; 128 bits for the fast engine's
// coordinates below 2^31, where each term is below 2^63).
template <typename Acc, typename RingT>
Acc twice_signed_area_in(const RingT& ring) {
  Acc sum = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = ring[i];
    const auto& b = ring[(i + 1) % n];
    sum += as_accumulator<Acc>(a.x) * b.y - as_accumulator<Acc>(a.y) * b.x;
  }
  return sum;
}

} // namespace penshape::detail
