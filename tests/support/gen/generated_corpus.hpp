#pragma once
// The generated stand-ins for the real corpora, as folders for tests that iterate over files: a
// $1-layout stroke corpus and the polygon suite, written once under the build folder (by
// whichever test asks first; safe when tests run in parallel) from fixed seeds.
#include <cstdint>
#include <filesystem>

namespace penshape::gen {

inline constexpr std::uint64_t kCorpusSeed = 2026;

// <build>/generated/strokes/dollar1: 3 subjects x 3 speeds x 5 of every single-stroke kind.
std::filesystem::path generated_dollar_dir();
// <build>/generated/polygons: polygon_suite(kCorpusSeed) as x-y files.
std::filesystem::path generated_polygon_dir();

} // namespace penshape::gen
