// Writes the generated corpora once (see generated_corpus.hpp): into a private temporary folder,
// then renamed into place, so a test never sees a half-written corpus.
#include "generated_corpus.hpp"

#include <cstdio>
#include <fstream>
#include <functional>
#include <random>
#include <string>

#include "polygon_gen.hpp"
#include "stroke_files.hpp"
#include "stroke_gen.hpp"

namespace penshape::gen {
namespace {

namespace fs = std::filesystem;

// A fingerprint of what the generators make now: in the folder's name, so that a changed
// generator writes a new folder instead of reusing stale files.
std::string fingerprint() {
  std::string all;
  for (const auto& e : single_stroke_corpus(kCorpusSeed, 1, 1)) all += to_jsonl(e.drawing, "");
  for (const auto& p : polygon_suite(kCorpusSeed)) all += p.text;
  char hex[24];
  std::snprintf(hex, sizeof hex, "%016zx", std::hash<std::string>{}(all));
  return hex;
}

fs::path materialize(const std::string& name, const std::function<void(const fs::path&)>& fill) {
  static const std::string version = fingerprint();
  fs::path target = fs::path(PENSHAPE_BINARY_DIR) / "generated" / version / name;
  std::error_code ec;
  if (fs::is_directory(target, ec)) return target;
  fs::create_directories(target.parent_path());
  const fs::path tmp = target.parent_path() / (".tmp-" + std::to_string(std::random_device{}()) +
                                               "-" + target.filename().string());
  fill(tmp);
  fs::rename(tmp, target, ec);
  if (ec) fs::remove_all(tmp, ec); // another test made it first
  return target;
}

} // namespace

fs::path generated_dollar_dir() {
  return materialize("strokes/dollar1", [](const fs::path& dir) {
    write_dollar_corpus(dir, single_stroke_corpus(kCorpusSeed, 3, 5));
  });
}

fs::path generated_polygon_dir() {
  return materialize("polygons", [](const fs::path& dir) {
    fs::create_directories(dir);
    for (const auto& p : polygon_suite(kCorpusSeed))
      std::ofstream(dir / (p.name + ".txt")) << p.text;
  });
}

} // namespace penshape::gen
