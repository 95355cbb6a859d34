#include "support/dollar1.hpp"

#include <regex>
#include <stdexcept>

#include "test_data.hpp"

namespace penshape::test {

std::vector<PointD> read_dollar1(const std::string& path) {
  const std::string text = read_file(path);
  static const std::regex point(R"re(<Point\s+X="(-?[0-9.]+)"\s+Y="(-?[0-9.]+)")re");
  std::vector<PointD> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), point);
       it != std::sregex_iterator(); ++it) {
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2])});
  }
  if (out.empty()) throw std::runtime_error("no points in " + path);
  return out;
}

} // namespace penshape::test
