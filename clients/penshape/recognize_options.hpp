#pragma once
// `penshape recognize`: its command line (the help text and the options it sets).
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "penshape/core/group_recognize.hpp"

namespace penshape::cli {

struct RecognizeOptions {
  RecognizerConfig recognizer;
  GroupingConfig grouping;   // enabled unless --no-group
  bool on_ink = false;       // --ink
  bool pressure = false;     // --pressure
  bool json = false;         // --json
  bool labels = false;       // --labels
  bool snap_writing = false; // --snap-writing: writing strokes are recognized too
  bool help = false;         // --help
  std::optional<std::string> svg_dir;
  std::vector<std::string> inputs; // FILE|DIR arguments
};

extern const char* const kRecognizeHelp;

// Throws UsageError for bad or missing arguments (not when --help is given).
RecognizeOptions parse_recognize_options(std::span<const std::string_view> args);

} // namespace penshape::cli
