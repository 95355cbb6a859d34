#pragma once
// Small two-column tables read in both directions: an enum and its names (or another enum), a
// character and its escape. One table serves a to_string and its parse, or a conversion and its
// inverse, so the two can never drift apart.
#include <array>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>

namespace penshape {

template <typename A, typename B, std::size_t N>
using LookupTable = std::array<std::pair<A, B>, N>;

// The second column of the row whose first is `key`, or `fallback` when no row has it.
template <typename A, typename B, std::size_t N>
[[nodiscard]] constexpr B lookup_or(const LookupTable<A, B, N>& table, const A& key,
                                    const std::type_identity_t<B>& fallback) {
  for (const auto& [a, b] : table) {
    if (a == key) return b;
  }
  return fallback;
}

// The first column of the row whose second is `value`, if any.
template <typename A, typename B, std::size_t N, typename V>
[[nodiscard]] constexpr std::optional<A> reverse_lookup(const LookupTable<A, B, N>& table,
                                                        const V& value) {
  for (const auto& [a, b] : table) {
    if (b == value) return a;
  }
  return std::nullopt;
}

} // namespace penshape
