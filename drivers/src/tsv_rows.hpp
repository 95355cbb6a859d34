#pragma once
// The two data tables (tablets.tsv, families.tsv) share one text form: rows of tab-separated
// columns, '#' comment lines and blank lines ignored, Windows line ends tolerated.
#include <cstddef>
#include <string_view>
#include <vector>

namespace penshape::drivers::tsv {

enum class Empty { kKeep, kSkip };

// `s` cut at every `sep`; empty pieces kept (a blank table column means something) or skipped
// (runs of separators inside a notation).
std::vector<std::string_view> split(std::string_view s, char sep, Empty empty);

// Calls row(line_number, line, columns) for every data line, 1-based line numbers; `columns`
// says whether an empty column is kept.
template <typename Row>
void for_each_row(std::string_view tsv, Empty columns, Row&& row) {
  std::size_t line_no = 0;
  for (std::string_view line : split(tsv, '\n', Empty::kKeep)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line.front() == '#') continue;
    row(line_no, line, split(line, '\t', columns));
  }
}

} // namespace penshape::drivers::tsv
