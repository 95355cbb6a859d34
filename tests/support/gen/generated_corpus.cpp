// Writes the generated corpora once (see generated_corpus.hpp): into a private temporary folder,
// then renamed into place, so a test never sees a half-written corpus.
#include "generated_corpus.hpp"

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

fs::path materialize(const std::string& name, const std::function<void(const fs::path&)>& fill) {
  // The seed and the generator version are in the folder's name: a changed generator makes a
  // new folder rather than reusing stale files.
  const fs::path target = fs::path(PENSHAPE_BINARY_DIR) / "generated" / name;
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
  return materialize("strokes-v1/dollar1", [](const fs::path& dir) {
    write_dollar_corpus(dir, single_stroke_corpus(kCorpusSeed, 3, 5));
  });
}

fs::path generated_polygon_dir() {
  return materialize("polygons-v1", [](const fs::path& dir) {
    fs::create_directories(dir);
    for (const auto& p : polygon_suite(kCorpusSeed))
      std::ofstream(dir / (p.name + ".txt")) << p.text;
  });
}

} // namespace penshape::gen
