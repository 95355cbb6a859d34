#pragma once
// Generated drawings written as the files the CLI and the tests read: $1 gesture-log XML (one
// stroke, integer pixels, milliseconds), JSON lines (strokes with pressure and their label), and
// a whole generated corpus laid out like the $1 logs (sNN/<speed>/<kind>NN.xml).
#include <filesystem>
#include <string>

#include "stroke_gen.hpp"

namespace penshape::gen {

// A $1 gesture log of one stroke; `name` is the Name attribute (e.g. "circle03").
std::string to_dollar_xml(const GenStroke& stroke, const std::string& name, int subject,
                          Speed speed);

// One JSON line per stroke of the drawing: points [x, y, t, pressure], name and label (the
// kind). Strokes of one drawing share its name.
std::string to_jsonl(const Drawing& drawing, const std::string& name);

// Writes every entry as <dir>/sNN/<speed>/<kind>NN.xml (the $1 logs' layout); returns the count.
std::size_t write_dollar_corpus(const std::filesystem::path& dir,
                                const std::vector<CorpusEntry>& entries);

} // namespace penshape::gen
