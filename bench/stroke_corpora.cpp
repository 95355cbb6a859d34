// Reading the labelled stroke corpora (stroke_corpora.hpp).
#include "stroke_corpora.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "dollar_xml.hpp"

namespace penshape::bench {
namespace {

std::vector<std::filesystem::path> files_under(const std::filesystem::path& root,
                                               const std::string& extension) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(root)) return files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.is_regular_file() && e.path().extension() == extension) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Points [x, y, t] of one JSON-lines stroke (the corpus's own format: numbers only).
std::vector<StrokePoint> json_points(const std::string& line) {
  static const std::regex point(R"(\[(-?[0-9.eE+-]+),(-?[0-9.eE+-]+),(-?[0-9.eE+-]+)\])");
  std::vector<StrokePoint> out;
  for (auto it = std::sregex_iterator(line.begin(), line.end(), point);
       it != std::sregex_iterator(); ++it) {
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3])});
  }
  return out;
}

} // namespace

std::vector<Drawing> load_dollar1(const std::filesystem::path& root) {
  std::vector<Drawing> out;
  for (const auto& f : files_under(root, ".xml")) {
    dollar::Gesture g = dollar::read_dollar_xml(f);
    Drawing d;
    d.corpus = "dollar1";
    d.file = f.string();
    d.label = g.kind();
    d.subject = "dollar1/s" + (g.subject.empty() ? std::string("?") : g.subject);
    d.strokes.push_back(std::move(g.points));
    out.push_back(std::move(d));
  }
  return out;
}

std::vector<Drawing> load_gestures(const std::filesystem::path& root) {
  std::vector<Drawing> out;
  for (const auto& f : files_under(root, ".jsonl")) {
    Drawing d;
    d.corpus = "gestures";
    d.file = f.string();
    // Directory "<source>-<class>"; file "<Source>__<device or group>__<writer>__...".
    const std::string dir = f.parent_path().filename().string();
    d.label = dir.substr(dir.find('-') + 1);
    const std::string stem = f.filename().string();
    const std::size_t a = stem.find("__"), b = stem.find("__", a + 2), c = stem.find("__", b + 2);
    d.subject = "gestures/" + stem.substr(0, a) + "-" +
                (c == std::string::npos ? stem : stem.substr(b + 2, c - b - 2));
    std::ifstream in(f);
    std::string line;
    while (std::getline(in, line)) {
      std::vector<StrokePoint> pts = json_points(line);
      if (!pts.empty()) d.strokes.push_back(std::move(pts));
    }
    if (!d.strokes.empty()) out.push_back(std::move(d));
  }
  return out;
}

} // namespace penshape::bench
