#pragma once
// Where test data lives, in one place: the data bundled with the repository (tests/data,
// recordings/) that every clone has, and the optional larger shared corpus (../shared/data).
// Tests that need the shared corpus skip, saying why, where it is absent; they never fail for it.
#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>

namespace penshape::test {

// The repository's root, and its bundled data folders.
std::filesystem::path source_dir();
std::filesystem::path bundled_data_dir(); // tests/data
std::filesystem::path recordings_dir();   // recordings/

// The shared corpus: $PENSHAPE_SHARED_DATA_DIR when set (even to an empty folder), else the
// CMake cache variable PENSHAPE_SHARED_DATA_DIR. nullopt when that folder holds no data.
std::optional<std::filesystem::path> shared_data_dir();
// The folder that holds the shared corpus when present, for messages.
std::string shared_data_location();
// A file or folder of the shared corpus; nullopt when the corpus or that entry is absent.
std::optional<std::filesystem::path> shared_path(const std::string& relative);
// A file named by its place in the shared corpus's layout (e.g. "polygons/authors_S.txt"): the
// bundled copy in tests/data when the repository has one, else the shared corpus's; nullopt when
// neither has it. tests/data mirrors the corpus's layout for the subset it bundles.
std::optional<std::filesystem::path> data_path(const std::string& relative);
// A folder to iterate over for tests that sample a collection (e.g. "strokes/dollar1"): the
// shared corpus's when present, else the bundled subset (which may be smaller).
std::filesystem::path collection_dir(const std::string& relative);

// The file's bytes; throws std::runtime_error naming the file when it cannot be read.
std::string read_file(const std::filesystem::path& path);
// data_path(relative) as a string, for command lines; throws when no copy exists. For files
// tests/data bundles.
std::string data_file(const std::string& relative);
// read_file(data_file(relative)).
std::string read_data(const std::string& relative);

} // namespace penshape::test

// In a test body (or SetUp): binds `var` to data_path(relative), or skips the test with the reason
// when no copy exists (the file is not bundled and the shared corpus is absent).
#define PENSHAPE_DATA_OR_SKIP(var, relative)                                                      \
  const std::filesystem::path var = [&] {                                                         \
    auto penshape_found_ = ::penshape::test::data_path(relative);                                 \
    return penshape_found_ ? *penshape_found_ : std::filesystem::path{};                          \
  }();                                                                                            \
  if (var.empty())                                                                                \
  GTEST_SKIP() << "needs " << (relative) << ", which is not bundled in tests/data: it is in the " \
               << "shared data corpus (" << ::penshape::test::shared_data_location()              \
               << "); set PENSHAPE_SHARED_DATA_DIR to run it"

// In a test body (or SetUp): binds `var` to the shared corpus entry `relative`, or skips the test
// with the reason when the corpus or the entry is absent.
#define PENSHAPE_SHARED_OR_SKIP(var, relative)                                \
  const std::filesystem::path var = [&] {                                     \
    auto penshape_found_ = ::penshape::test::shared_path(relative);           \
    return penshape_found_ ? *penshape_found_ : std::filesystem::path{};      \
  }();                                                                        \
  if (var.empty())                                                            \
  GTEST_SKIP() << "needs the shared data corpus (" << (relative) << " under " \
               << ::penshape::test::shared_data_location()                    \
               << "); set PENSHAPE_SHARED_DATA_DIR to run it"
