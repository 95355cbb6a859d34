// Stripe-by-stripe positive union (see stripe_union.hpp).
#include "stripe_union.hpp"

#include <algorithm>
#include <atomic>
#include <vector>

#include "clipper_stage.hpp"
#include "int_geometry.hpp"

namespace penshape::fast {
namespace {

namespace cl = ClipperLib;

// y where the segment p-q crosses the vertical line at x (strictly between their x), rounded
// to nearest; the ends are put in x order first so the result does not depend on direction.
cl::cInt crossing_y(cl::IntPoint p, cl::IntPoint q, cl::cInt x) {
  if (q.X < p.X) std::swap(p, q);
  const Int128 num = static_cast<Int128>(x - p.X) * static_cast<Int128>(q.Y - p.Y);
  const auto den = static_cast<Int128>(q.X - p.X); // > 0
  // floor((2 num + den) / (2 den)): round half up.
  Int128 t = 2 * num + den;
  Int128 f = t / (2 * den);
  if (t % (2 * den) != 0 && t < 0) --f;
  return p.Y + static_cast<cl::cInt>(f);
}

// Appends p, dropping repeats and the middle of a run of points on one stripe line (the run
// only travels along the line: nothing strictly inside the stripe changes winding).
void emit(cl::Path& out, cl::IntPoint p, cl::cInt x0, cl::cInt x1) {
  if (!out.empty() && out.back() == p) return;
  const std::size_t n = out.size();
  if (n >= 2 && (p.X == x0 || p.X == x1) && out[n - 1].X == p.X && out[n - 2].X == p.X) {
    out.back() = p;
    return;
  }
  out.push_back(p);
}

} // namespace

cl::Paths clamp_to_stripe(const cl::Paths& paths, cl::cInt x0, cl::cInt x1) {
  cl::Paths out;
  for (const cl::Path& path : paths) {
    const std::size_t n = path.size();
    const bool enters = std::any_of(path.begin(), path.end(),
                                    [&](const cl::IntPoint& p) { return p.X > x0 && p.X < x1; });
    bool spans = false; // an edge may cross the whole stripe with no vertex inside it
    for (std::size_t i = 0; i < n && !enters && !spans; ++i) {
      const cl::IntPoint& a = path[i];
      const cl::IntPoint& b = path[(i + 1) % n];
      spans = std::min(a.X, b.X) <= x0 && std::max(a.X, b.X) >= x1;
    }
    if (n < 3 || (!enters && !spans)) continue;
    cl::Path clamped;
    clamped.reserve(n + 8);
    for (std::size_t i = 0; i < n; ++i) {
      const cl::IntPoint a = path[i];
      const cl::IntPoint b = path[(i + 1) % n];
      emit(clamped, {std::clamp(a.X, x0, x1), a.Y}, x0, x1);
      // Crossings of the open edge with the two lines, in order along the edge.
      const cl::cInt first = a.X < b.X ? x0 : x1;
      const cl::cInt second = a.X < b.X ? x1 : x0;
      for (const cl::cInt x : {first, second}) {
        if ((a.X < x && x < b.X) || (b.X < x && x < a.X))
          emit(clamped, {x, crossing_y(a, b, x)}, x0, x1);
      }
    }
    if (clamped.size() >= 3) out.push_back(std::move(clamped));
  }
  return out;
}

namespace {

// Set by benches and tests before any decision runs; read by every union (relaxed: a flag).
std::atomic<bool> g_turn_wide{true};

// Whether the paths' bounding box is wider than it is tall.
bool wider_than_tall(const cl::Paths& paths) {
  bool any = false;
  cl::cInt x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (const cl::Path& path : paths) {
    for (const cl::IntPoint& p : path) {
      x0 = any ? std::min(x0, p.X) : p.X;
      x1 = any ? std::max(x1, p.X) : p.X;
      y0 = any ? std::min(y0, p.Y) : p.Y;
      y1 = any ? std::max(y1, p.Y) : p.Y;
      any = true;
    }
  }
  return any && x1 - x0 > y1 - y0;
}

// union_positive in the paths' own frame: stripe by stripe when they are large.
void union_upright(const cl::Paths& paths, cl::PolyTree& tree, std::size_t stripe_vertices) {
  std::vector<cl::cInt> xs;
  for (const cl::Path& path : paths) {
    for (const cl::IntPoint& p : path) xs.push_back(p.X);
  }
  const std::size_t stripes = stripe_vertices == 0 ? 1 : xs.size() / stripe_vertices;
  cl::Clipper all;
  if (stripes <= 1) {
    all.AddPaths(paths, cl::ptSubject, true);
    all.Execute(cl::ctUnion, tree, cl::pftPositive, cl::pftPositive);
    return;
  }
  // Stripe lines at quantiles of the vertices' x: about stripe_vertices vertices each.
  std::vector<cl::cInt> lines;
  lines.push_back(*std::min_element(xs.begin(), xs.end()));
  for (std::size_t k = 1; k < stripes; ++k) {
    const auto nth = xs.begin() + static_cast<std::ptrdiff_t>(k * xs.size() / stripes);
    std::nth_element(xs.begin(), nth, xs.end());
    if (*nth > lines.back()) lines.push_back(*nth);
  }
  const cl::cInt right = *std::max_element(xs.begin(), xs.end());
  if (right > lines.back()) lines.push_back(right);
  cl::cInt bottom = paths.front().front().Y, top = bottom;
  for (const cl::Path& path : paths) {
    for (const cl::IntPoint& p : path) {
      bottom = std::min(bottom, p.Y);
      top = std::max(top, p.Y);
    }
  }
  // Each stripe's paths are clamped to the stripe widened by a margin, so the runs the clamping
  // leaves along its lines (zero-width bridges in Clipper's output) fall outside the stripe;
  // one Clipper pass then takes the positive region of the clamped paths within the stripe.
  constexpr cl::cInt kMargin = 2;
  for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
    const cl::cInt x0 = lines[k], x1 = lines[k + 1];
    cl::Clipper stripe;
    stripe.AddPaths(clamp_to_stripe(paths, x0 - kMargin, x1 + kMargin), cl::ptSubject, true);
    stripe.AddPath({{x0, bottom - 1}, {x1, bottom - 1}, {x1, top + 1}, {x0, top + 1}}, cl::ptClip,
                   true);
    cl::Paths piece;
    stripe.Execute(cl::ctIntersection, piece, cl::pftPositive, cl::pftNonZero);
    all.AddPaths(piece, cl::ptSubject, true);
  }
  all.Execute(cl::ctUnion, tree, cl::pftPositive, cl::pftPositive);
}

} // namespace

void set_turn_wide_paths(bool turn) { g_turn_wide.store(turn, std::memory_order_relaxed); }

void union_positive(const cl::Paths& paths, cl::PolyTree& tree, std::size_t stripe_vertices) {
  if (!g_turn_wide.load(std::memory_order_relaxed) || !wider_than_tall(paths)) {
    union_upright(paths, tree, stripe_vertices);
    return;
  }
  // A quarter turn clockwise, (x, y) -> (y, -x), keeps every path's orientation and winding
  // numbers; |coordinates| <= 2^31, so the negation is exact. The result turns back.
  cl::Paths turned = paths;
  for (cl::Path& path : turned) {
    for (cl::IntPoint& p : path) p = {p.Y, -p.X};
  }
  union_upright(turned, tree, stripe_vertices);
  for (cl::PolyNode* node = tree.GetFirst(); node != nullptr; node = node->GetNext()) {
    for (cl::IntPoint& p : node->Contour) p = {-p.Y, p.X};
  }
}

} // namespace penshape::fast
