#pragma once
// Test drawings for `penshape snap`, made from hand-drawn strokes of the project's stroke
// generator (tests/support/gen: circles, a rectangle, a triangle, a spiral): an Inkscape SVG with
// Pencil paths and a Calligraphy outline, and a Xournal++ document with pressure widths; both also
// hold text, an image and a second layer.
#include <filesystem>
#include <string>
#include <vector>

#include "penshape/core/polygon_set.hpp" // PointD

namespace penshape::test {

// A gesture file's points, scaled so the larger side of its box is `size`, its box's corner
// at (x0, y0).
std::vector<PointD> placed_gesture(const std::string& file, double x0, double y0, double size);

// What a fixture holds, in root (page) coordinates, for the checks.
struct FixtureStroke {
  std::string id;             // SVG id, or "page 1 layer L stroke S"
  std::vector<PointD> points; // the raw stroke as drawn (page coordinates)
  double width = 0.0;         // pen width (outline width for calligraphy)
  std::string expect;         // the class a snap should give ("" : stays as drawn)
};

struct Fixture {
  std::string text; // the document (.xopp: the XML before gzip)
  std::vector<FixtureStroke> strokes;
};

// Layer "Ink" (id layer1): pencil-circle (absolute C), pencil-rect (relative c),
// pencil-pigtail (L), callig-triangle (filled outline with arc caps), text#label, image#photo.
// Layer "Notes" (id layer2, transform translate(0,20)): notes-circle (blue), text#note.
// 800 x 600 user units.
Fixture inkscape_fixture();

// One 800 x 600 pt page. Layer 1: a circle with per-point pressure widths, a rectangle, a
// pigtail, a text and an image; layer 2: a circle and a text.
Fixture xopp_fixture();

// gzip of the bytes (zlib), as Xournal++ saves.
std::string gzip_bytes(const std::string& bytes);

void write_bytes(const std::filesystem::path& path, const std::string& bytes);

} // namespace penshape::test
