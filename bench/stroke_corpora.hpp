#pragma once
// Labelled real drawings for the recognizer benches, read from ../shared/data/strokes (never
// copied into the repository): the $1 logs (dollar1/sNN/speed/<class>NN.xml, one stroke each)
// and the gestures of other people (gestures/<source>-<class>/*.jsonl, one line per stroke).
// Each drawing knows its writer, so that rules can be scored on writers they were not tuned on.
#include <filesystem>
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::bench {

struct Drawing {
  std::string corpus;  // "dollar1" or "gestures"
  std::string subject; // the writer: "dollar1/s02", "gestures/MMG-41", ...
  std::string label;   // the class drawn, without source or digits: "circle", "line", ...
  std::string file;
  std::vector<std::vector<StrokePoint>> strokes; // in drawing order
};

// Every $1 log under root (none when root does not exist).
std::vector<Drawing> load_dollar1(const std::filesystem::path& root);
// Every gesture drawing under root (none when root does not exist).
std::vector<Drawing> load_gestures(const std::filesystem::path& root);

} // namespace penshape::bench
