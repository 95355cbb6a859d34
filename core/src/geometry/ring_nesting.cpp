// ring_parents: a left-to-right sweep over all edges (lexicographic order of points, which
// handles vertical edges and shared x-coordinates as a tiny shear would). The status holds the
// edges crossing the sweep line, ordered bottom to top: boundaries do not cross, so the order
// of two edges never changes while both are in it. At the lexicographically smallest vertex v
// of a ring R, the first edge above R's upper edge at v that belongs to another ring S decides:
// the point just below that edge and v are joined by a segment that meets only R's boundary,
// so they lie in the same rings other than R. If S's interior is below that edge, S is R's
// innermost container; otherwise R and S share their container, which is S's parent (S's
// smallest vertex comes earlier in the sweep, so it is known).
#include "geometry/ring_nesting.hpp"

#include <algorithm>
#include <numeric>
#include <set>

namespace penshape::detail {
namespace {

bool lex_less(const FilteredPoint& a, const FilteredPoint& b) { return compare_lex(a, b) < 0; }

struct Edge {
  const FilteredPoint* left;  // lexicographically smaller endpoint
  const FilteredPoint* right; // larger endpoint
  std::size_t ring;
  bool interior_below; // the ring's interior lies just below (to the right of left -> right)
};

// a below b, for edges both crossing the sweep line and not crossing each other.
struct Below {
  const std::vector<Edge>* edges;
  bool operator()(std::size_t ia, std::size_t ib) const {
    if (ia == ib) return false;
    const Edge& a = (*edges)[ia];
    const Edge& b = (*edges)[ib];
    if (a.left->exact == b.left->exact) return orientation(*a.left, *a.right, *b.right) > 0;
    if (lex_less(*b.left, *a.left)) {
      int o = orientation(*b.left, *b.right, *a.left);
      if (o == 0) o = orientation(*b.left, *b.right, *a.right);
      return o < 0;
    }
    int o = orientation(*a.left, *a.right, *b.left);
    if (o == 0) o = orientation(*a.left, *a.right, *b.right);
    return o > 0;
  }
};

struct Vertex {
  std::size_t ring;
  std::size_t index;
};

} // namespace

std::vector<long> ring_parents(const std::vector<std::vector<FilteredPoint>>& rings) {
  std::vector<Edge> edges;
  std::vector<Vertex> vertices;
  std::vector<std::size_t> first_edge(rings.size());
  std::vector<std::size_t> lowest(rings.size(), 0); // lexicographically smallest vertex
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const auto& pts = rings[k];
    const std::size_t n = pts.size();
    for (std::size_t i = 1; i < n; ++i) {
      if (lex_less(pts[i], pts[lowest[k]])) lowest[k] = i;
    }
    // The smallest vertex is convex: its turn gives the ring's orientation.
    const std::size_t m = lowest[k];
    const bool ccw = orientation(pts[(m + n - 1) % n], pts[m], pts[(m + 1) % n]) > 0;
    first_edge[k] = edges.size();
    for (std::size_t i = 0; i < n; ++i) {
      const FilteredPoint& a = pts[i];
      const FilteredPoint& b = pts[(i + 1) % n];
      const bool forward = lex_less(a, b);
      // Interior on the left of the ring's direction when counterclockwise.
      edges.push_back({forward ? &a : &b, forward ? &b : &a, k, ccw != forward});
      vertices.push_back({k, i});
    }
  }
  std::sort(vertices.begin(), vertices.end(), [&](const Vertex& u, const Vertex& v) {
    return lex_less(rings[u.ring][u.index], rings[v.ring][v.index]);
  });

  std::set<std::size_t, Below> status(Below{&edges});
  std::vector<std::set<std::size_t, Below>::iterator> where(edges.size(), status.end());
  std::vector<long> parent(rings.size(), -1);
  for (const Vertex& v : vertices) {
    const std::size_t n = rings[v.ring].size();
    const std::size_t e_in = first_edge[v.ring] + (v.index + n - 1) % n; // ends or starts at v
    const std::size_t e_out = first_edge[v.ring] + v.index;
    const FilteredPoint* p = &rings[v.ring][v.index];
    // Edges ending here leave the status before the ones starting here enter it.
    for (const std::size_t e : {e_in, e_out}) {
      if (edges[e].right == p && where[e] != status.end()) {
        status.erase(where[e]);
        where[e] = status.end();
      }
    }
    for (const std::size_t e : {e_in, e_out}) {
      if (edges[e].left == p) where[e] = status.insert(e).first;
    }
    if (v.index != lowest[v.ring]) continue;
    // Both edges start at the ring's smallest vertex: walk up from the upper one.
    auto it = std::max(where[e_in], where[e_out],
                       [&](auto a, auto b) { return status.key_comp()(*a, *b); });
    for (++it; it != status.end() && edges[*it].ring == v.ring; ++it) {
    }
    if (it == status.end()) continue;
    const Edge& hit = edges[*it];
    parent[v.ring] = hit.interior_below ? static_cast<long>(hit.ring) : parent[hit.ring];
  }
  return parent;
}

} // namespace penshape::detail
