// `penshape snap` leaves writing alone (issue #24): on note pages (generated cursive writing at
// ~5 mm letters with shapes of 20-60 mm between the lines; and real UNIPEN handwriting under the
// shared-data skip) as SVG (CSS pixels, and mm through a viewBox) and as Xournal++ documents,
// >= 98% of the writing strokes come out byte for byte while the shapes are snapped;
// --snap-writing snaps writing again; --json says each stroke's intent.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "generated_ink.hpp"
#include "note_documents.hpp"
#include "run_command.hpp"
#include "snap/page_intent.hpp"
#include "snap_fixtures.hpp"
#include "test_data.hpp"

namespace penshape::test {
namespace {

namespace fs = std::filesystem;
using notes::NoteDocument;
using notes::NoteStroke;
const std::string kCli = PENSHAPE_CLI;

// The generated note page: six lines of words, shapes below every second line.
std::vector<NoteStroke> generated_page() {
  std::vector<NoteStroke> page;
  for (ink::PageStroke& s : ink::note_page(6, true))
    page.push_back({std::move(s.points), s.writing});
  return page;
}

class SnapWriting : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("penshape-snap-writing-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Snaps the document (written as `name`) with `args`; OUT's bytes, the output in `log` (stdout
  // only with --json, whose lines stderr would cut).
  std::string snap(const std::string& name, const NoteDocument& doc, const std::string& args,
                   std::string& log) {
    const char* err = args.find("--json") == std::string::npos ? " 2>&1" : " 2>/dev/null";
    write_bytes(dir_ / name, doc.xml); // .xopp as plain XML: snap reads it by content
    const auto r = run_command("(" + kCli + " snap --local " + args + " " + (dir_ / name).string() +
                               " " + (dir_ / "out.xml").string() + err + ")");
    log = r.out;
    EXPECT_EQ(r.exit_code, 0) << r.out.substr(0, 2000);
    std::ifstream in(dir_ / "out.xml", std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  fs::path dir_;
};

// An SVG user unit in mm: width over viewBox width when both say so, else a CSS pixel.
TEST(SvgUnits, MillimetresPerUserUnit) {
  const auto mm = [](const char* svg) {
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_string(svg));
    return snap::svg_mm_per_unit(doc.document_element());
  };
  EXPECT_DOUBLE_EQ(mm(R"(<svg width="210mm" viewBox="0 0 210 297"/>)"), 1.0);
  EXPECT_DOUBLE_EQ(mm(R"(<svg width="8.5in" viewBox="0,0,850,1100"/>)"), 0.254);
  EXPECT_DOUBLE_EQ(mm(R"(<svg width="21cm" viewBox="0 0 2100 2970"/>)"), 0.1);
  for (const char* px :
       {R"(<svg width="400" height="300"/>)", R"(<svg viewBox="0 0 40 30"/>)",
        R"(<svg width="100%" viewBox="0 0 40 30"/>)", R"(<svg width="10mm" viewBox="0 0 0 30"/>)",
        R"(<svg width="10em" viewBox="0 0 10 30"/>)"}) {
    EXPECT_DOUBLE_EQ(mm(px), snap::kSvgPixelMm) << px;
  }
}

// Writing kept byte for byte (>= 98%), shapes snapped (>= 95%), with the figures printed.
void expect_writing_left_alone(const NoteDocument& doc, const std::string& out,
                               const std::string& what) {
  const std::size_t writing = notes::count(doc, true), shapes = notes::count(doc, false);
  const std::size_t kept = notes::kept(doc, out, true);
  const std::size_t snapped = shapes - notes::kept(doc, out, false);
  std::printf("%s: %zu of %zu writing strokes kept byte for byte, %zu of %zu shapes snapped\n",
              what.c_str(), kept, writing, snapped, shapes);
  EXPECT_GE(kept * 100, writing * 98) << what << ": " << kept << " of " << writing;
  EXPECT_GE(snapped * 100, shapes * 95) << what << ": " << snapped << " of " << shapes;
}

TEST_F(SnapWriting, SvgInPixelsLeavesWritingAlone) {
  const NoteDocument doc = notes::svg_notes(generated_page(), false);
  std::string log;
  expect_writing_left_alone(doc, snap("notes.svg", doc, "", log), "SVG in px");
  EXPECT_NE(log.find("judged writing, left as drawn"), std::string::npos) << log;
}

TEST_F(SnapWriting, SvgInMillimetresLeavesWritingAlone) {
  const NoteDocument doc = notes::svg_notes(generated_page(), true);
  std::string log;
  expect_writing_left_alone(doc, snap("notes.svg", doc, "", log), "SVG in mm");
}

TEST_F(SnapWriting, XoppLeavesWritingAlone) {
  const NoteDocument doc = notes::xopp_notes({generated_page()});
  std::string log;
  expect_writing_left_alone(doc, snap("notes.xopp", doc, "", log), ".xopp");
}

// --snap-writing turns the filter off: writing strokes are snapped again.
TEST_F(SnapWriting, SnapWritingSnapsWritingAgain) {
  for (const bool xopp : {false, true}) {
    const NoteDocument doc =
        xopp ? notes::xopp_notes({generated_page()}) : notes::svg_notes(generated_page(), false);
    const std::string name = xopp ? "notes.xopp" : "notes.svg";
    std::string log;
    const std::size_t writing = notes::count(doc, true);
    const std::size_t kept = notes::kept(doc, snap(name, doc, "--snap-writing", log), true);
    std::printf("%s --snap-writing: %zu of %zu writing strokes kept\n", name.c_str(), kept,
                writing);
    EXPECT_LT(kept * 10, writing * 9) << name << ": " << kept << " of " << writing << " kept";
    EXPECT_EQ(log.find("judged writing"), std::string::npos) << log;
  }
}

// --json: every stroke read is named with its intent; replacements say theirs.
TEST_F(SnapWriting, JsonSaysEachStrokesIntent) {
  const NoteDocument doc = notes::svg_notes(generated_page(), false);
  std::string log;
  snap("notes.svg", doc, "--json", log);
  std::size_t strokes = 0, writing = 0, replacements = 0;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with("{")) continue;
    const auto j = nlohmann::json::parse(line);
    if (j.contains("element")) {
      ++strokes;
      writing += j.at("intent") == "writing" ? 1 : 0;
    } else if (j.contains("class")) {
      ++replacements;
      EXPECT_EQ(j.at("intent"), "drawing") << line;
    }
  }
  // Dots are no strokes snap reads (left as drawn with a warning).
  EXPECT_GT(strokes, doc.elements.size() * 8 / 10);
  EXPECT_GE(writing * 100, notes::count(doc, true) * 90);
  EXPECT_GT(replacements, 0u);
}

// Real handwriting (UNIPEN items, read at run time) on Xournal++ pages, generated shapes between
// the items: >= 98% of the writing strokes kept byte for byte.
std::vector<NoteStroke> read_item(const fs::path& file) {
  std::vector<NoteStroke> strokes;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    NoteStroke& s = strokes.emplace_back();
    // Named: a range-for over a temporary's member would read freed memory.
    const auto item = nlohmann::json::parse(line);
    for (const auto& p : item.at("points")) {
      s.points.push_back({p.at(0).get<double>(), p.at(1).get<double>(), 0.0});
    }
  }
  return strokes;
}

// Appends the item's strokes at vertical offset y (items have their box's corner at (20, 20)).
double place(std::vector<NoteStroke> item, double y, std::vector<NoteStroke>& page) {
  double bottom = y;
  for (NoteStroke& s : item) {
    for (StrokePoint& p : s.points) {
      p.y += y - 20;
      bottom = std::max(bottom, p.y);
    }
    page.push_back(std::move(s));
  }
  return bottom + 6;
}

TEST_F(SnapWriting, RealHandwritingOnXoppPagesIsLeftAlone) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/handwriting-unipen/pages");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<std::vector<NoteStroke>> pages(1);
  double y = 20, t = 0;
  for (std::size_t k = 0; k < files.size(); ++k) {
    y = place(read_item(files[k]), y, pages.back());
    if (k % 8 == 7) { // shapes between the lines, as on a note page
      for (ink::Points& s : ink::shapes_at(20, y, t)) pages.back().push_back({std::move(s), false});
      y += 62;
    }
    if (y > 330) pages.emplace_back(), y = 20;
  }
  const NoteDocument doc = notes::xopp_notes(pages);
  std::string log;
  const std::string out = snap("unipen.xopp", doc, "", log);
  const std::size_t writing = notes::count(doc, true), kept = notes::kept(doc, out, true);
  std::printf(
      "UNIPEN on %zu .xopp pages: %zu of %zu writing strokes kept byte for byte; %zu of "
      "%zu shapes snapped\n",
      pages.size(), kept, writing, notes::count(doc, false) - notes::kept(doc, out, false),
      notes::count(doc, false));
  EXPECT_GE(kept * 100, writing * 98) << kept << " of " << writing;
}

} // namespace
} // namespace penshape::test
