// The recognizer's figures on real and generated strokes (see generated_accuracy.hpp).
#include "generated_accuracy.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "dollar_xml.hpp"
#include "generated_corpus.hpp"
#include "penshape/core/group_recognize.hpp"
#include "stroke_gen.hpp"

namespace penshape::bench {
namespace {

const std::map<std::string, std::set<std::string>>& real_truth() {
  static const std::map<std::string, std::set<std::string>> truth{
      {"circle", {"circle", "ellipse"}},   {"rectangle", {"rectangle", "square", "quadrilateral"}},
      {"triangle", {"triangle"}},          {"pigtail", {"freeform"}},
      {"question_mark", {"freeform"}},     {"left_curly_brace", {"freeform"}},
      {"right_curly_brace", {"freeform"}}, {"delete_mark", {"freeform"}}};
  return truth;
}

struct Tally {
  int shapes = 0, shapes_ok = 0, non_shapes = 0, non_shape_snaps = 0;
  void add(const LabelledStroke& s, const std::string& got) {
    if (s.truth.count("freeform") != 0) {
      ++non_shapes;
      non_shape_snaps += got != "freeform" ? 1 : 0;
    } else {
      ++shapes;
      shapes_ok += s.truth.count(got) != 0 ? 1 : 0;
    }
  }
  void print(const std::string& row) const {
    std::printf(
        "  %-16s shapes correct %4d / %4d = %5.1f%%   non-shape snaps %3d / %4d = %4.1f%%\n",
        row.c_str(), shapes_ok, shapes, 100.0 * shapes_ok / std::max(shapes, 1), non_shape_snaps,
        non_shapes, 100.0 * non_shape_snaps / std::max(non_shapes, 1));
  }
};

} // namespace

std::vector<LabelledStroke> real_dollar_strokes(const std::string& root) {
  std::vector<LabelledStroke> out;
  std::error_code ec;
  if (!std::filesystem::is_directory(root, ec)) return out;
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.is_regular_file() && e.path().extension() == ".xml") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    LabelledStroke s;
    s.kind = std::regex_replace(f.stem().string(), std::regex("[0-9]+$"), "");
    s.subject = f.parent_path().parent_path().filename().string();
    if (const auto it = real_truth().find(s.kind); it != real_truth().end()) s.truth = it->second;
    s.points = dollar::read_dollar_xml(f).points;
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<LabelledStroke> generated_strokes() {
  std::vector<LabelledStroke> out;
  for (const auto& e : gen::single_stroke_corpus(gen::kCorpusSeed, 3, 5)) {
    std::string subject = "g"; // appended: g++ 12 warns falsely (-Wrestrict) on "g" + string
    subject += std::to_string(e.subject);
    out.push_back({e.drawing.kind, subject, e.drawing.truth, e.drawing.strokes.front().points});
  }
  return out;
}

void print_labelled_accuracy(const std::string& corpus,
                             const std::vector<LabelledStroke>& strokes) {
  Tally all, comparable;
  // The kinds both corpora share in kind: circles, rectangles, triangles, and non-shapes other
  // than dots (arrows need grouping, dots are a case of their own).
  const auto is_comparable = [](const LabelledStroke& s) {
    return s.kind == "circle" || s.kind == "rectangle" || s.kind == "triangle" ||
           (s.truth.count("freeform") != 0 && s.kind != "dot");
  };
  std::map<std::string, Tally> by_subject;
  std::map<std::string, std::map<std::string, int>> by_kind;
  for (const LabelledStroke& s : strokes) {
    if (s.truth.empty() || s.points.size() < 2) continue;
    StrokeInput alone;
    alone.samples = s.points;
    const std::string got = to_string(recognize_strokes({&alone, 1}).front().recognition.shape);
    all.add(s, got);
    if (is_comparable(s)) comparable.add(s, got);
    by_subject[s.subject].add(s, got);
    ++by_kind[s.kind][got];
  }
  std::printf(
      "%s: recognizer figures (each stroke alone, as `penshape recognize` reads it; "
      "default configuration)\n",
      corpus.c_str());
  all.print("whole corpus");
  comparable.print("$1-like kinds");
  for (const auto& [subject, tally] : by_subject) tally.print("subject " + subject);
  for (const auto& [kind, classes] : by_kind) {
    std::printf("  %-16s", kind.c_str());
    for (const auto& [c, n] : classes) std::printf(" %s %d", c.c_str(), n);
    std::printf("\n");
  }
}

} // namespace penshape::bench
