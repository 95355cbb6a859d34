#include "support/shared_data.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace penshape::test {

std::string shared_data_dir() {
  if (const char* env = std::getenv("PENSHAPE_SHARED_DATA_DIR"); env != nullptr && *env) return env;
  return PENSHAPE_SHARED_DATA_DIR;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string read_shared(const std::string& relative) {
  return read_file(shared_data_dir() + "/" + relative);
}

} // namespace penshape::test
