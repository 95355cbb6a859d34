#pragma once
// Multi-stroke drawings built from real single strokes (the $1 gesture logs): shapes cut at their
// corners into 2-4 pieces (gaps, overshoots, reversed and reordered pieces, pen-up pauses),
// arrows whole and cut at the tip, two separate shapes one after the other, and two non-shape
// gestures close together. Written independently of the recognizer (corners are found here by
// a brute-force largest-area search), shared by the grouping tests and the grouping benchmark.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "dollar_xml.hpp"
#include "made_shapes.hpp"
#include "penshape/core/recognize.hpp"

namespace penshape::cases {

using Points = std::vector<StrokePoint>;

struct Gesture {
  std::string file;
  std::string kind; // "rectangle", "arrow", ...
  Points points;    // t in seconds
};

inline Gesture read_dollar(const std::filesystem::path& path) {
  dollar::Gesture read = dollar::read_dollar_xml(path);
  Gesture g;
  g.file = path.string();
  g.kind = read.kind();
  g.points = std::move(read.points);
  return g;
}

// Every $1 gesture under `root` (…/strokes/dollar1), sorted by path.
inline std::vector<Gesture> dollar_gestures(const std::filesystem::path& root) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.is_regular_file() && e.path().extension() == ".xml") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<Gesture> out;
  out.reserve(files.size());
  for (const auto& f : files) out.push_back(read_dollar(f));
  return out;
}

inline double area_of(const std::vector<std::size_t>& idx, const Points& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < idx.size(); ++i) {
    const StrokePoint& u = p[idx[i]];
    const StrokePoint& v = p[idx[(i + 1) % idx.size()]];
    a += u.x * v.y - u.y * v.x;
  }
  return std::abs(a) / 2.0;
}

// Sample indices of the k corners (3 or 4) of a closed stroke: the k samples, in path order,
// spanning the largest polygon (brute force on every ceil(n / 28)-th sample).
inline std::vector<std::size_t> corners(const Points& p, std::size_t k) {
  const std::size_t stride = std::max<std::size_t>(1, (p.size() + 27) / 28);
  std::vector<std::size_t> c;
  for (std::size_t i = 0; i < p.size(); i += stride) c.push_back(i);
  std::vector<std::size_t> best, cur(k);
  double best_area = -1.0;
  const std::size_t n = c.size();
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      for (std::size_t d = b + 1; d < n; ++d) {
        if (k == 3) {
          cur = {c[a], c[b], c[d]};
          const double ar = area_of(cur, p);
          if (ar > best_area) best_area = ar, best = cur;
          continue;
        }
        for (std::size_t e = d + 1; e < n; ++e) {
          cur = {c[a], c[b], c[d], c[e]};
          const double ar = area_of(cur, p);
          if (ar > best_area) best_area = ar, best = cur;
        }
      }
    }
  }
  return best;
}

inline double stroke_size(const Points& p) {
  double xl = p[0].x, xh = xl, yl = p[0].y, yh = yl;
  for (const auto& s : p) {
    xl = std::min(xl, s.x), xh = std::max(xh, s.x), yl = std::min(yl, s.y), yh = std::max(yh, s.y);
  }
  return std::hypot(xh - xl, yh - yl);
}

// A piece re-timed to start at `start`, keeping its sample intervals (reversed pieces too).
inline Points retimed(Points piece, bool reverse, double start) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < piece.size(); ++i) {
    dt.push_back(std::max(1e-3, std::abs(piece[i].t - piece[i - 1].t)));
  }
  if (reverse) {
    std::reverse(piece.begin(), piece.end());
    std::reverse(dt.begin(), dt.end());
  }
  double t = start;
  for (std::size_t i = 0; i < piece.size(); ++i) {
    piece[i].t = t;
    if (i < dt.size()) t += dt[i];
  }
  return piece;
}

// Variation number v (any integer) picks the gaps, overshoots, reversals, order and pauses.
struct Variation {
  std::size_t gap_samples = 0;   // samples dropped at each cut
  double overshoot = 0.0;        // pixels added past each cut, along the stroke
  std::size_t reverse_every = 0; // piece j reversed when (j + v) % reverse_every == 0 (0: none)
  bool rotate_order = false;     // first piece drawn last
  bool swap_first_two = false;
  double pause = 0.3; // seconds between pieces
};

inline Variation variation(std::size_t v) {
  Variation out;
  out.gap_samples = v % 3;
  out.overshoot = (v % 4 == 3) ? 4.0 : 0.0;
  out.reverse_every = (v % 5 == 0) ? 0 : 2 + v % 2;
  out.rotate_order = v % 2 == 1;
  out.swap_first_two = v % 6 == 4;
  out.pause = 0.2 + 0.15 * static_cast<double>(v % 5);
  return out;
}

// Cuts `p` at the sample indices `cuts` (ascending, interior) into pieces and applies the
// variation. Each piece keeps at least 3 samples.
inline std::vector<Points> cut(const Points& p, std::vector<std::size_t> cuts, const Variation& v,
                               std::size_t seed) {
  std::vector<Points> pieces;
  std::size_t from = 0;
  cuts.push_back(p.size() - 1);
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    const std::size_t lo = k == 0 ? 0 : from + v.gap_samples;
    std::size_t hi = cuts[k];
    Points piece(p.begin() + static_cast<std::ptrdiff_t>(std::min(lo, hi)),
                 p.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
    if (v.overshoot > 0 && k + 1 < cuts.size() && piece.size() >= 2) {
      const StrokePoint a = piece[piece.size() - 2], b = piece.back();
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      if (len > 0) {
        piece.push_back({b.x + v.overshoot * (b.x - a.x) / len,
                         b.y + v.overshoot * (b.y - a.y) / len, b.t + 0.01});
      }
    }
    if (piece.size() >= 3) pieces.push_back(std::move(piece));
    from = cuts[k];
  }
  if (v.rotate_order && pieces.size() > 1)
    std::rotate(pieces.begin(), pieces.begin() + 1, pieces.end());
  if (v.swap_first_two && pieces.size() > 1) std::swap(pieces[0], pieces[1]);
  double t = 0.0;
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const bool rev = v.reverse_every > 0 && (j + seed) % v.reverse_every == 0;
    pieces[j] = retimed(pieces[j], rev, t);
    t = pieces[j].back().t + v.pause;
  }
  return pieces;
}

// A closed stroke cut at `pieces - 1` of its corners `c` (sample indices in path order) away
// from the stroke's ends, where it starts and closes: a window of them starting at v. Empty when
// it has too few such corners.
inline std::vector<Points> cut_at_corners(const Points& p, const std::vector<std::size_t>& c,
                                          std::size_t pieces, std::size_t v) {
  std::vector<std::size_t> interior;
  const std::size_t margin = p.size() / 10 + 2;
  for (const std::size_t i : c) {
    if (i > margin && i + margin < p.size()) interior.push_back(i);
  }
  if (interior.size() + 1 < pieces) return {};
  std::vector<std::size_t> chosen;
  for (std::size_t j = 0; j + 1 < pieces; ++j) {
    chosen.push_back(interior[(v + j) % interior.size()]);
  }
  std::sort(chosen.begin(), chosen.end());
  chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
  if (chosen.size() + 1 != pieces) return {};
  return cut(p, chosen, variation(v), v);
}

// A closed shape stroke (a triangle or a rectangle) cut at `pieces - 1` of its corners.
inline std::vector<Points> cut_shape(const Gesture& g, std::size_t pieces, std::size_t v) {
  return cut_at_corners(g.points, corners(g.points, g.kind == "triangle" ? 3 : 4), pieces, v);
}

// An arrow stroke cut at its tip into shaft and head.
inline std::vector<Points> cut_arrow_at(const Points& points, std::size_t tip, std::size_t v) {
  if (tip < 3 || tip + 3 >= points.size()) return {};
  Variation var = variation(v);
  var.overshoot = 0.0; // past the tip would lengthen the shaft, not the drawing
  return cut(points, {tip}, var, v);
}

// An arrow stroke cut at its tip (the sample farthest from its start) into shaft and head.
inline std::vector<Points> cut_arrow(const Gesture& g, std::size_t v) {
  return cut_arrow_at(g.points, arrow_tip(g.points), v);
}

// A round stroke (a circle) cut into `pieces` at evenly spaced samples, the first cut a share of
// a piece that v picks (a circle is cut anywhere: it has no corners), none near its ends.
inline std::vector<Points> cut_round(const Points& p, std::size_t pieces, std::size_t v) {
  if (pieces < 2 || p.size() < 8 * pieces) return {};
  const double piece = static_cast<double>(p.size()) / static_cast<double>(pieces);
  const double offset = (0.3 + 0.4 * static_cast<double>(v % 5) / 4.0) * piece;
  std::vector<std::size_t> cuts;
  for (std::size_t j = 0; j + 1 < pieces; ++j) {
    cuts.push_back(static_cast<std::size_t>(offset + static_cast<double>(j) * piece));
  }
  return cut(p, cuts, variation(v), v);
}

// Two strokes one after the other: the second moved so that its bounding box starts `gap`
// pixels to the right of the first's, drawn `pause` seconds after it.
inline std::vector<Points> side_by_side(const Points& a, const Points& b, double gap,
                                        double pause) {
  double ax = -INFINITY, bx = INFINITY, ay = 0, by = 0;
  for (const auto& s : a) ax = std::max(ax, s.x), ay += s.y / static_cast<double>(a.size());
  for (const auto& s : b) bx = std::min(bx, s.x), by += s.y / static_cast<double>(b.size());
  Points first = retimed(a, false, 0.0);
  Points second = retimed(b, false, first.back().t + pause);
  for (auto& s : second) s.x += ax + gap - bx, s.y += ay - by;
  return {first, second};
}

} // namespace penshape::cases
