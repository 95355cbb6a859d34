// Exact lower bounds on the distance between Clipper's union and the exact union (exact_union.hpp).
#include "exact_union.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "ink/ink_union.hpp"

namespace penshape::test {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

struct Exact {
  mpq_class x, y;
};

Exact exact(const IntPoint& p) {
  return {mpq_class(mpz_class(static_cast<long>(p.X))),
          mpq_class(mpz_class(static_cast<long>(p.Y)))};
}

mpq_class squared_distance(const Exact& p, const Exact& a, const Exact& b) {
  const mpq_class dx = b.x - a.x, dy = b.y - a.y;
  const mpq_class t = (p.x - a.x) * dx + (p.y - a.y) * dy, len = dx * dx + dy * dy;
  const auto from = [&](const Exact& e) -> mpq_class {
    return (p.x - e.x) * (p.x - e.x) + (p.y - e.y) * (p.y - e.y);
  };
  if (t <= 0 || len == 0) return from(a);
  if (t >= len) return from(b);
  const mpq_class c = (p.x - a.x) * dy - (p.y - a.y) * dx;
  return c * c / len;
}

// Squared distance from p to the paths' edges (the boundary).
mpq_class squared_distance(const Exact& p, const Paths& paths) {
  mpq_class best = -1;
  for (const Path& path : paths) {
    for (std::size_t i = 0; i < path.size(); ++i) {
      const mpq_class d = squared_distance(p, exact(path[i]), exact(path[(i + 1) % path.size()]));
      if (best < 0 || d < best) best = d;
    }
  }
  return best;
}

// Whether p is in the non-zero filled region of the paths (boundary included).
bool inside(const Exact& p, const Paths& paths) {
  if (squared_distance(p, paths) == 0) return true;
  int winding = 0;
  for (const Path& path : paths) {
    for (std::size_t i = 0; i < path.size(); ++i) {
      const Exact a = exact(path[i]), b = exact(path[(i + 1) % path.size()]);
      const mpq_class side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
      if (a.y <= p.y && b.y > p.y && side > 0) ++winding;
      if (a.y > p.y && b.y <= p.y && side < 0) --winding;
    }
  }
  return winding != 0;
}

double distance_if_outside(const Exact& p, const Paths& region) {
  return inside(p, region) ? 0.0 : std::sqrt(squared_distance(p, region).get_d());
}

// The exact crossing points of the edges of different paths.
std::vector<Exact> crossings(const Paths& paths) {
  std::vector<Exact> out;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    for (std::size_t j = i + 1; j < paths.size(); ++j) {
      for (std::size_t a = 0; a < paths[i].size(); ++a) {
        for (std::size_t b = 0; b < paths[j].size(); ++b) {
          const Exact p = exact(paths[i][a]), p2 = exact(paths[i][(a + 1) % paths[i].size()]);
          const Exact q = exact(paths[j][b]), q2 = exact(paths[j][(b + 1) % paths[j].size()]);
          const mpq_class d = (p2.x - p.x) * (q2.y - q.y) - (p2.y - p.y) * (q2.x - q.x);
          if (d == 0) continue;
          const mpq_class t = ((q.x - p.x) * (q2.y - q.y) - (q.y - p.y) * (q2.x - q.x)) / d;
          const mpq_class s = ((q.x - p.x) * (p2.y - p.y) - (q.y - p.y) * (p2.x - p.x)) / d;
          if (t < 0 || t > 1 || s < 0 || s > 1) continue;
          out.push_back({p.x + t * (p2.x - p.x), p.y + t * (p2.y - p.y)});
        }
      }
    }
  }
  return out;
}

// The points of the paths' edges on the horizontal lines y = ys (edges crossing them).
std::vector<Exact> on_lines(const Paths& paths, const std::set<cInt>& ys) {
  std::vector<Exact> out;
  for (const Path& path : paths) {
    for (std::size_t i = 0; i < path.size(); ++i) {
      const IntPoint& a = path[i];
      const IntPoint& b = path[(i + 1) % path.size()];
      for (auto y = ys.upper_bound(std::min(a.Y, b.Y)); y != ys.end() && *y < std::max(a.Y, b.Y);
           ++y) {
        const Exact ea = exact(a), eb = exact(b);
        const mpq_class t = (mpq_class(mpz_class(static_cast<long>(*y))) - ea.y) / (eb.y - ea.y);
        out.push_back({ea.x + t * (eb.x - ea.x), mpq_class(mpz_class(static_cast<long>(*y)))});
      }
    }
  }
  return out;
}

std::set<cInt> vertex_ys(const Paths& a, const Paths& b) {
  std::set<cInt> ys;
  for (const Paths* paths : {&a, &b}) {
    for (const Path& path : *paths) {
      for (const IntPoint& v : path) ys.insert(v.Y);
    }
  }
  return ys;
}

} // namespace

double union_error_lower_bound(const Paths& pieces, bool scanlines) {
  ClipperLib::PolyTree tree;
  if (!ink_detail::clipper_union(pieces, tree)) return HUGE_VAL;
  Paths out;
  ClipperLib::PolyTreeToPaths(tree, out);
  double worst = 0;
  for (const Path& path : out) {
    for (const IntPoint& v : path) worst = std::max(worst, distance_if_outside(exact(v), pieces));
  }
  for (const Exact& p : crossings(pieces)) worst = std::max(worst, distance_if_outside(p, out));
  for (const Path& path : pieces) {
    for (const IntPoint& v : path) worst = std::max(worst, distance_if_outside(exact(v), out));
  }
  if (!scanlines) return worst;
  const std::set<cInt> ys = vertex_ys(pieces, out);
  for (const Exact& p : on_lines(pieces, ys)) worst = std::max(worst, distance_if_outside(p, out));
  for (const Exact& p : on_lines(out, ys)) worst = std::max(worst, distance_if_outside(p, pieces));
  return worst;
}

} // namespace penshape::test
