#include "support/dollar1.hpp"

#include <stdexcept>

#include "dollar_xml.hpp"

namespace penshape::test {

std::vector<PointD> read_dollar1(const std::string& path) {
  std::vector<PointD> out;
  for (const StrokePoint& p : dollar::read_dollar_xml(path).points) out.push_back({p.x, p.y});
  if (out.empty()) throw std::runtime_error("no points in " + path);
  return out;
}

} // namespace penshape::test
