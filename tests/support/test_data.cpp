// Where test data lives: project-made folders by the compile-time source path, the shared corpus
// by one override (environment first, then the CMake cache variable).
#include "test_data.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace penshape::test {

std::filesystem::path source_dir() { return PENSHAPE_SOURCE_DIR; }
std::filesystem::path bundled_data_dir() { return source_dir() / "tests" / "data"; }
std::filesystem::path recordings_dir() { return source_dir() / "recordings"; }

std::string shared_data_location() {
  if (const char* env = std::getenv("PENSHAPE_SHARED_DATA_DIR"); env != nullptr && *env) return env;
  return PENSHAPE_SHARED_DATA_DIR;
}

std::optional<std::filesystem::path> shared_data_dir() {
  const std::filesystem::path dir = shared_data_location();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return std::nullopt;
  if (std::filesystem::directory_iterator(dir, ec) == std::filesystem::directory_iterator{})
    return std::nullopt;
  return dir;
}

std::optional<std::filesystem::path> shared_path(const std::string& relative) {
  const auto dir = shared_data_dir();
  if (!dir) return std::nullopt;
  std::filesystem::path p = *dir / relative;
  std::error_code ec;
  if (!std::filesystem::exists(p, ec)) return std::nullopt;
  return p;
}

std::optional<std::filesystem::path> data_path(const std::string& relative) {
  return shared_path(relative);
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

} // namespace penshape::test

namespace penshape::test {

std::string data_file(const std::string& relative) {
  const auto path = data_path(relative);
  if (!path) {
    throw std::runtime_error(relative + " is not in the shared corpus (" + shared_data_location() +
                             "); outside data is never bundled in the repository");
  }
  return path->string();
}

std::string read_data(const std::string& relative) { return read_file(data_file(relative)); }

} // namespace penshape::test
