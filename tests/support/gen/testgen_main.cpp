// penshape-testgen: writes the project's generated test data as files, for what needs files (the
// recordings/ made with `penshape synthesize-recording`, fuzz seeds, docs' examples, a $1-layout
// corpus). C++ tests call the generators directly instead.
//   penshape-testgen corpus DIR [--seed N] [--subjects S] [--per-kind K]   $1-layout XML files
//   penshape-testgen drawings DIR --seed N KIND...   one XML file per drawing (NN-KIND.xml) and
//                                                    DIR/expected (the truth, one line each)
//   penshape-testgen descriptor NAME FILE            a pen descriptor of pen_descriptor_specs(),
//                                                    or vendor-graphire (vendor_pen_descriptor)
//   penshape-testgen polygons DIR [--seed N]         polygon_suite() as x-y files
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "descriptor_gen.hpp"
#include "polygon_gen.hpp"
#include "stroke_files.hpp"
#include "stroke_gen.hpp"

namespace fs = std::filesystem;
using namespace penshape::gen;

namespace {

struct Args {
  std::vector<std::string> positional;
  std::uint64_t seed = 1;
  int subjects = 3;
  int per_kind = 5;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 2; i < argc; ++i) {
    const std::string s = argv[i];
    const bool has_value = i + 1 < argc;
    if (s == "--seed" && has_value) {
      a.seed = std::stoull(argv[++i]);
    } else if (s == "--subjects" && has_value) {
      a.subjects = std::stoi(argv[++i]);
    } else if (s == "--per-kind" && has_value) {
      a.per_kind = std::stoi(argv[++i]);
    } else {
      a.positional.push_back(s);
    }
  }
  return a;
}

void write(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string join(const std::set<std::string>& classes) {
  std::string out;
  for (const auto& c : classes) out += (out.empty() ? "" : "|") + c;
  return out;
}

int drawings(const Args& a) {
  const fs::path dir = a.positional.at(0);
  fs::create_directories(dir);
  StrokeGenerator gen(a.seed);
  std::string expected;
  for (std::size_t i = 1; i < a.positional.size(); ++i) {
    const Drawing d = gen.draw(a.positional[i]);
    char name[64];
    std::snprintf(name, sizeof name, "%02zu-%s", i, d.kind.c_str());
    if (d.strokes.size() != 1) throw std::runtime_error(d.kind + " is not a one-stroke kind");
    write(dir / (std::string(name) + ".xml"),
          to_dollar_xml(d.strokes.front(), name, 1, Speed::kMedium));
    expected += join(d.truth) + "\n";
  }
  write(dir / "expected", expected);
  return 0;
}

int descriptor(const Args& a) {
  if (a.positional.at(0) == "vendor-graphire") { // the Graphire protocol's report: ID 2, 8 bytes
    const auto bytes = vendor_pen_descriptor(2, 8);
    write(a.positional.at(1), std::string(bytes.begin(), bytes.end()));
    return 0;
  }
  for (const auto& spec : pen_descriptor_specs()) {
    if (spec.name != a.positional.at(0)) continue;
    const auto bytes = pen_descriptor(spec);
    write(a.positional.at(1), std::string(bytes.begin(), bytes.end()));
    return 0;
  }
  throw std::runtime_error("no descriptor named " + a.positional.at(0));
}

int polygons(const Args& a) {
  fs::create_directories(a.positional.at(0));
  for (const auto& p : polygon_suite(a.seed))
    write(fs::path(a.positional.at(0)) / (p.name + ".txt"), p.text);
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  try {
    const std::string command = argc > 1 ? argv[1] : "";
    const Args a = parse(argc, argv);
    if (command == "corpus") {
      write_dollar_corpus(a.positional.at(0), single_stroke_corpus(a.seed, a.subjects, a.per_kind));
      return 0;
    }
    if (command == "drawings") return drawings(a);
    if (command == "descriptor") return descriptor(a);
    if (command == "polygons") return polygons(a);
    std::fprintf(
        stderr,
        "usage: penshape-testgen corpus|drawings|descriptor|polygons ... (see the source)\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "penshape-testgen: %s\n", e.what());
    return 2;
  }
}
