#pragma once
// The one reader of $1 gesture logs (Wobbrock et al. 2007), for the CLI, the tests and the
// benches: one `<Gesture Name="..." Subject="...">` element with `<Point X="..." Y="..." T="..."/>`
// children (pixels, milliseconds; T optional). Parsed with pugixml; a UTF-8 BOM is allowed.
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::dollar {

// "origin:line: problem".
struct DollarXmlError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Gesture {
  std::string name;                // the Name attribute, e.g. "triangle03" (may be empty)
  std::string subject;             // the Subject attribute (may be empty)
  std::size_t line = 0;            // where the <Gesture> element starts
  std::vector<StrokePoint> points; // x, y in pixels; t in seconds (T / 1000; 0 without T)

  // The name without its trailing digits: "triangle03" -> "triangle".
  [[nodiscard]] std::string kind() const;
};

// Throws DollarXmlError: XML that does not parse, no or several <Gesture> elements, a <Point>
// without X or Y, a coordinate or time that is not a finite number. A gesture may have no points.
Gesture parse_dollar_xml(std::string_view text, const std::string& origin);
Gesture read_dollar_xml(const std::filesystem::path& path); // also when it cannot be read

} // namespace penshape::dollar
