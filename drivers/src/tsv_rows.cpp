// Splitting for the tab-separated data tables (see tsv_rows.hpp).
#include "tsv_rows.hpp"

namespace penshape::drivers::tsv {

std::vector<std::string_view> split(std::string_view s, char sep, Empty empty) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == sep) {
      if (i > start || empty == Empty::kKeep) out.push_back(s.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

} // namespace penshape::drivers::tsv
