#pragma once
// Reading pen strokes from files for `penshape recognize`.
//
// Formats (chosen by extension):
//  - `.xml`: a $1 gesture log (Wobbrock et al. 2007): one `<Gesture Name="...">` element with
//    `<Point X="..." Y="..." T="..."/>` children (pixels, milliseconds). A UTF-8 BOM is allowed.
//    The stroke's name is the gesture's Name attribute.
//  - `.jsonl` / `.ndjson`: JSON lines, one stroke per non-blank line:
//        {"points": [[x, y, t], [x, y, t], ...], "name": "circle01", "label": "circle"}
//    `points` is required: arrays of 2, 3 or 4 finite numbers (x, y, optionally t in seconds,
//    optionally the pen pressure in [0, 1] after t); pressure is given for every point or none.
//    `name` (any string) and `label` (the expected class or a gesture name) are optional; other
//    keys are ignored. The stroke's line number names it in messages. Parsed with nlohmann-json
//    (string escapes decoded as JSON says). Refused, naming file and line: a stroke with fewer
//    than two points, t given for some points only, times that repeat or go backwards along a
//    stroke, a stroke starting before the previous one ended (lines are strokes in drawing
//    order), numbers that are not finite.
// Malformed input throws StrokeFileError with "file:line: problem".
#include <stdexcept>
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::cli {

struct StrokeFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FileStroke {
  std::string file;
  std::size_t line = 0; // line where the stroke starts
  std::string name;     // gesture name / "name" key, may be empty
  std::string label;    // "label" key (JSON lines), else empty
  std::vector<StrokePoint> points;
  std::vector<double> pressure; // one per point in [0, 1] (JSON lines), or empty: none
  bool timed = false;           // t given (JSON lines with 3 or 4 numbers per point; $1 XML)
};

std::vector<FileStroke> read_stroke_file(const std::string& path);

// FILE or DIR arguments to the stroke files they name: directories are searched recursively for
// .xml, .jsonl and .ndjson files, in sorted order. Throws StrokeFileError for a missing path.
std::vector<std::string> collect_stroke_files(const std::vector<std::string>& args);

} // namespace penshape::cli
