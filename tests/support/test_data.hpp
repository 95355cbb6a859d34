#pragma once
// Where test data lives, in one place. The repository holds only data the project made
// (tests/data: generated adversarial polygons; recordings/: generated tablet sessions); tests of
// a bare clone run on those and on the generators in tests/support/gen. Real data from elsewhere
// lives only in the shared corpus (../shared/data), never in the repository: tests that need it
// skip, saying why, where it is absent; they never fail for it.
#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>

namespace penshape::test {

// The repository's root, and its folders of project-made data.
std::filesystem::path source_dir();
std::filesystem::path bundled_data_dir(); // tests/data (project-made only)
std::filesystem::path recordings_dir();   // recordings/ (generated, see recordings/SOURCES.md)

// The shared corpus: $PENSHAPE_SHARED_DATA_DIR when set (even to an empty folder), else the
// CMake cache variable PENSHAPE_SHARED_DATA_DIR. nullopt when that folder holds no data.
std::optional<std::filesystem::path> shared_data_dir();
// The folder that holds the shared corpus when present, for messages.
std::string shared_data_location();
// A file or folder of the shared corpus; nullopt when the corpus or that entry is absent.
std::optional<std::filesystem::path> shared_path(const std::string& relative);
// shared_path(relative); kept for the tests that name shared files by their corpus path.
std::optional<std::filesystem::path> data_path(const std::string& relative);

// The file's bytes; throws std::runtime_error naming the file when it cannot be read.
std::string read_file(const std::filesystem::path& path);
// A shared corpus file as a string, for command lines; throws, saying the corpus is absent,
// when it is. Call it only after PENSHAPE_SHARED_OR_SKIP.
std::string data_file(const std::string& relative);
// read_file(data_file(relative)).
std::string read_data(const std::string& relative);

} // namespace penshape::test

// In a test body (or SetUp): binds `var` to the shared corpus entry `relative`, or skips the test
// with the reason when the corpus or the entry is absent.
#define PENSHAPE_SHARED_OR_SKIP(var, relative)                                \
  const std::filesystem::path var = [&] {                                     \
    auto penshape_found_ = ::penshape::test::shared_path(relative);           \
    return penshape_found_ ? *penshape_found_ : std::filesystem::path{};      \
  }();                                                                        \
  if ((var).empty())                                                          \
  GTEST_SKIP() << "needs the shared data corpus (" << (relative) << " under " \
               << ::penshape::test::shared_data_location()                    \
               << "); set PENSHAPE_SHARED_DATA_DIR to run it"
