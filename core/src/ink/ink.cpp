// The ink polygon: union of per-segment hulls of pen disks with Clipper (int64), in chunks of the
// stroke (ink_chunks.hpp), see ink.hpp.
#include "penshape/core/ink.hpp"

#include <clipper.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string>

#include "ink_chunks.hpp"
#include "ink_union.hpp"
#include "penshape/core/base.hpp"

namespace penshape {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

constexpr double kMaxCoordinateMm = 1e9;
// Grid coordinates stay within Clipper's range (2^62); cross products need 128 bits.
constexpr double kMaxGridUnits = 1e18;
__extension__ using Int128 = __int128;

constexpr std::size_t kMaxDiskVertices = 4096;

// The smallest k (a multiple of 4, >= 8) with r·(1 - cos(π/k)) <= allowed; throws when that
// needs more than kMaxDiskVertices.
// The bound is rounded outwards: every operation's rounding taken against us.
double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
double down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

double sum_up(std::initializer_list<double> terms) {
  double s = 0.0;
  for (const double t : terms) s = up(s + t);
  return s;
}

// r·(1 - cos(π/k)) from above: π/k bounded above, its cosine (glibc: within 1 ulp) taken two
// ulps down; cosine decreases on [0, π/8].
double disk_sagitta_up(double r, std::size_t k) {
  const double angle = up(up(std::numbers::pi) / static_cast<double>(k));
  return up(r * up(1.0 - down(down(std::cos(angle)))));
}

std::size_t polygon_vertices(double r, double allowed) {
  const double ratio = allowed / r;
  if (ratio >= 1) return 8;
  const double angle = std::acos(1.0 - ratio); // π/k must not exceed this
  const double k_min = angle > 0 ? std::numbers::pi / angle : HUGE_VAL;
  if (!(k_min <= static_cast<double>(kMaxDiskVertices))) {
    throw InvalidInput("the requested ink error " + std::to_string(allowed * 2) +
                       " mm needs more than " + std::to_string(kMaxDiskVertices) +
                       " disk vertices for radius " + std::to_string(r) + " mm");
  }
  std::size_t k = std::max<std::size_t>(8, 4 * static_cast<std::size_t>(std::ceil(k_min / 4)));
  while (k < kMaxDiskVertices &&
         r * (1.0 - std::cos(std::numbers::pi / static_cast<double>(k))) > allowed) {
    k += 4;
  }
  return k;
}

// Clipper's own arithmetic in a round join or end (ClipperOffset::DoRound): the unit vector is
// turned step by step by multiplying with the step's double cos and sin, so each step errs by a
// few ulps in its length and direction (16 ulps, 16 * 2^-53, is generous: two products and a
// sum per coordinate, the step's sin and cos within 2 ulps). After n steps an arc vertex is off
// the true circle by at most 16 n 2^-53 r, and the last chord, spanning that much more angle,
// gains as much sagitta again: 32 n 2^-53 r. A join or end turns at most half a turn, so
// n <= steps / 2 + 1 with Clipper's steps per turn pi / acos(1 - y / r), y = min(arc tolerance,
// r / 4) (both in the same unit; Clipper caps steps lower still for tiny radii). +2 covers the
// rounding of this estimate.
double clipper_turning(double r, double arc_tolerance) {
  const double ratio = std::min(arc_tolerance / r, 0.25);
  const double steps = std::numbers::pi / std::acos(1.0 - ratio);
  return up(up(up(steps / 2 + 2) * 32.0 * 0x1p-53) * r);
}

// Largest power of two <= v (v > 0), as 2^exponent.
int floor_log2(double v) { return static_cast<int>(std::floor(std::log2(v))); }

struct Grid {
  double scale = 1.0; // grid units per mm, 2^m
  cInt round(double mm) const { return static_cast<cInt>(std::llround(mm * scale)); }
};

// Convex hull (Andrew's monotone chain) of the given integer points, counterclockwise.
Path convex_hull(Path pts) {
  std::sort(pts.begin(), pts.end(), [](const IntPoint& a, const IntPoint& b) {
    return a.X < b.X || (a.X == b.X && a.Y < b.Y);
  });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  auto cross = [](const IntPoint& o, const IntPoint& a, const IntPoint& b) {
    const Int128 ax = a.X - o.X, ay = a.Y - o.Y, bx = b.X - o.X, by = b.Y - o.Y;
    return ax * by - ay * bx;
  };
  Path hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i - 1]) <= 0) --k;
    hull[k++] = pts[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

void check_finite(double v, const char* what, std::size_t i) {
  if (!std::isfinite(v)) {
    throw InvalidInput(std::string("sample ") + std::to_string(i) + ": " + what + " is not finite");
  }
}

// The ring in mm: grid is a power of two (plan_for), so each coordinate is an integer shifted.
Ring to_ring(const Path& path, double grid) {
  Ring ring;
  ring.reserve(path.size());
  for (const auto& p : path) {
    ring.push_back({ink_detail::on_grid(p.X, grid), ink_detail::on_grid(p.Y, grid)});
  }
  return ring;
}

void collect(const ClipperLib::PolyNode& node, double grid, PolygonSet& out) {
  // node is an outer contour; its children are holes, whose children are outer contours again.
  PolygonWithHoles polygon;
  polygon.outer = to_ring(node.Contour, grid);
  for (const ClipperLib::PolyNode* hole : node.Childs) {
    polygon.holes.push_back(to_ring(hole->Contour, grid));
    for (const ClipperLib::PolyNode* island : hole->Childs) collect(*island, grid, out);
  }
  out.polygons.push_back(std::move(polygon));
}

// Douglas-Peucker on (x, y, radius): keeps the ends and every sample whose distance to the kept
// chord, plus its radius's difference from the chord's interpolated radius, exceeds tau. Every
// removed sample is within tau of the simplified chain and every chord point within tau of the
// original chain (it sweeps from one kept sample to the next), so the swept regions differ by at
// most tau.
std::vector<InkSample> simplify(const std::vector<InkSample>& in, double tau) {
  if (in.size() <= 2) return in;
  std::vector<char> keep(in.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, in.size() - 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const InkSample& a = in[i];
    const InkSample& b = in[j];
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double worst = -1;
    std::size_t worst_k = i;
    for (std::size_t k = i + 1; k < j; ++k) {
      const InkSample& p = in[k];
      const double t =
          len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
      const double d = std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy) +
                       std::abs(p.radius - (a.radius + t * (b.radius - a.radius)));
      if (d > worst) {
        worst = d;
        worst_k = k;
      }
    }
    if (worst > tau) {
      keep[worst_k] = 1;
      stack.push_back({i, worst_k});
      stack.push_back({worst_k, j});
    }
  }
  std::vector<InkSample> out;
  for (std::size_t k = 0; k < in.size(); ++k) {
    if (keep[k]) out.push_back(in[k]);
  }
  return out;
}

} // namespace

namespace ink_detail {

double clipper_union_arithmetic(double magnitude) {
  const double above_doubles_half_units = magnitude >= 0x1p52 ? std::numbers::sqrt2 / 2 : 0.0;
  return up(up(64.0 * 0x1p-53 * magnitude) + above_doubles_half_units);
}

double clipper_topx_rounding(double magnitude) { return magnitude < 0x1p50 ? 0.5 + 0x1p-53 : 1.0; }

double clipper_union_sweep(double magnitude) {
  return up(2 * clipper_topx_rounding(magnitude) + up(128.0 * 0x1p-53 * magnitude));
}

double clipper_pinch_factor(const Paths& pieces) {
  const auto length = [](Int128 x, Int128 y) {
    return std::hypot(static_cast<double>(x), static_cast<double>(y));
  };
  double factor = 1.0;
  for (const Path& path : pieces) {
    if (path.size() < 3) continue; // Clipper drops it
    for (std::size_t i = 0; i < path.size(); ++i) {
      const IntPoint& v = path[i];
      const IntPoint& p = path[(i + path.size() - 1) % path.size()];
      const IntPoint& n = path[(i + 1) % path.size()];
      const Int128 ax = p.X - v.X, ay = p.Y - v.Y, bx = n.X - v.X, by = n.Y - v.Y;
      const Int128 turn = bx * ay - by * ax;            // (v - p) x (n - v): left turns are convex
      if (ax * bx + ay * by <= 0 || turn < 0) continue; // pi / 2 or more, or a notch
      if (turn == 0) return HUGE_VAL;                   // a spike: no bound
      // 1 / sin = |a| |b| / |a x b|: a few roundings each, 16 ulps cover them.
      const double ratio = length(ax, ay) * length(bx, by) / static_cast<double>(turn);
      factor = std::max(factor, up(ratio * (1 + 16 * 0x1p-53)));
    }
  }
  return factor;
}

Rational on_grid(ClipperLib::cInt v, double grid) {
  // GMP shifts the power of two in and cancels it against the other side: the canonical form
  // of v times exact(grid), without a product and its gcd per coordinate.
  const int exponent = std::ilogb(grid);
  Rational q(static_cast<long>(v));
  if (exponent < 0) {
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-exponent));
  } else {
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(exponent));
  }
  return q;
}

bool clipper_union(const Paths& pieces, ClipperLib::PolyTree& tree) {
  FedUnion fed;
  fed.add(pieces);
  return fed.execute(tree);
}

FedUnion::FedUnion() { clipper_.StrictlySimple(true); }

void FedUnion::add(const Paths& pieces) { clipper_.AddPaths(pieces, ClipperLib::ptSubject, true); }

bool FedUnion::execute(ClipperLib::PolyTree& tree) {
  return clipper_.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero,
                          ClipperLib::pftNonZero);
}

} // namespace ink_detail

std::vector<InkSample> ink_samples(const Stroke& stroke, const InkOptions& options) {
  const TabletInfo& t = stroke.tablet;
  const double sx = t.x_resolution > 0 ? 1.0 / t.x_resolution : 1.0;
  const double sy = t.y_resolution > 0 ? 1.0 / t.y_resolution : 1.0;
  const bool pressure = options.use_pressure && t.pressure_max > 0;
  std::vector<InkSample> out;
  out.reserve(stroke.samples.size());
  for (const PenSample& s : stroke.samples) {
    double r = options.radius_mm;
    if (pressure) {
      const double p = std::clamp(
          static_cast<double>(s.pressure) / static_cast<double>(t.pressure_max), 0.0, 1.0);
      r *= options.min_fraction + (1.0 - options.min_fraction) * std::pow(p, options.gamma);
    }
    out.push_back({static_cast<double>(s.x) * sx, static_cast<double>(s.y) * sy, r});
  }
  return out;
}

namespace ink_detail {

// The options' maximal error, after checking the options and the sample count.
double checked_max_error(const InkOptions& options, std::size_t total) {
  if (total == 0) throw InvalidInput("the stroke has no samples");
  if (total > options.max_samples) {
    throw InvalidInput("the strokes have " + std::to_string(total) +
                       " samples, over the limit of " + std::to_string(options.max_samples));
  }
  if (!(options.radius_mm > 0) || !std::isfinite(options.radius_mm)) {
    throw InvalidInput("the pen radius must be positive and finite");
  }
  if (!(options.min_fraction >= 0 && options.min_fraction <= 1) || !(options.gamma > 0) ||
      !std::isfinite(options.gamma)) {
    throw InvalidInput("the pressure curve needs min_fraction in [0, 1] and a finite gamma > 0");
  }
  const double max_error =
      options.max_error_mm == 0.0 ? options.radius_mm / 50 : options.max_error_mm;
  if (!(max_error > 0) || !std::isfinite(max_error)) {
    throw InvalidInput("the maximal error must be positive and finite");
  }
  return max_error;
}

// The largest radius and coordinate magnitude of the samples (mm), after checking each sample.
// Checks sample i and widens the reach by it.
void check_sample(const InkSample& sample, std::size_t i, Reach& reach) {
  check_finite(sample.x, "x", i);
  check_finite(sample.y, "y", i);
  check_finite(sample.radius, "radius", i);
  if (!(sample.radius > 0)) {
    throw InvalidInput("sample " + std::to_string(i) + ": radius must be positive");
  }
  if (std::abs(sample.x) > kMaxCoordinateMm || std::abs(sample.y) > kMaxCoordinateMm) {
    throw InvalidInput("sample " + std::to_string(i) + ": coordinate beyond 10^9 mm");
  }
  reach.r_min = std::min(reach.r_min, sample.radius);
  reach.r_max = std::max(reach.r_max, sample.radius);
  reach.extent = std::max({reach.extent, std::abs(sample.x), std::abs(sample.y)});
}

void widen_reach(const std::vector<InkSample>& samples, std::size_t j, Reach& reach) {
  if (samples.empty()) throw InvalidInput("stroke " + std::to_string(j) + " has no samples");
  for (std::size_t i = 0; i < samples.size(); ++i) check_sample(samples[i], i, reach);
}

Reach checked_reach(const std::vector<std::vector<InkSample>>& strokes) {
  Reach reach;
  for (std::size_t j = 0; j < strokes.size(); ++j) widen_reach(strokes[j], j, reach);
  if (reach.r_max > kMaxCoordinateMm) throw InvalidInput("the pen radius exceeds 10^9 mm");
  return reach;
}

Reach checked_reach(const std::vector<InkSample>& samples) {
  Reach reach;
  widen_reach(samples, 0, reach);
  if (reach.r_max > kMaxCoordinateMm) throw InvalidInput("the pen radius exceeds 10^9 mm");
  return reach;
}

void widen_checked_reach(const std::vector<InkSample>& samples, std::size_t from, Reach& reach) {
  for (std::size_t i = from; i < samples.size(); ++i) check_sample(samples[i], i, reach);
  if (reach.r_max > kMaxCoordinateMm) throw InvalidInput("the pen radius exceeds 10^9 mm");
}

} // namespace ink_detail

namespace {

using ink_detail::Plan;
using ink_detail::Reach;

// What an offset stroke goes through (the most of any piece): four roundings of half a grid
// diagonal (input points, offset vertices, the offset's own union, the final union) and two
// unions, each with its sweep decisions (ink_union.hpp). A hull stroke has two roundings (disk
// vertices, the final union) and one union.
constexpr double kOffsetRoundings = 4.0;
constexpr double kOffsetUnions = 2.0;
// Pen disks are drawn with at least this radius in grid units, so that no piece is thin enough
// for the final union to pinch it away whole (ink_union.hpp); the bound adds the difference.
constexpr double kMinDiskUnits = 4.0;

// A power of two with (roundings · sqrt(2) / 2 + unions · 2 rho) · grid <= max_error / 4, rho
// the rounding of Clipper's TopX (the grid-sized part of a union's sweep term, ink_union.hpp).
double grid_for(double max_error, double rho) {
  const double units = kOffsetRoundings * std::numbers::sqrt2 / 2 + kOffsetUnions * 2 * rho;
  return std::ldexp(1.0, floor_log2(max_error / 4 / units));
}

// The grid, with rho taken for the magnitude that grid gives (a coarser rho only refines it).
double choose_grid(double max_error, const Reach& reach) {
  const double rho = ink_detail::clipper_topx_rounding(0);
  const double grid = grid_for(max_error, rho);
  const double rho_there =
      ink_detail::clipper_topx_rounding((reach.extent + reach.r_max) / grid + kMinDiskUnits);
  return rho_there == rho ? grid : grid_for(max_error, rho_there);
}

} // namespace

namespace ink_detail {

Plan plan_for(double max_error, const Reach& reach) {
  Plan plan;
  plan.tau = max_error / 4;
  plan.grid = choose_grid(max_error, reach);
  plan.min_radius = kMinDiskUnits * plan.grid;
  const double r_max = std::max(reach.r_max, plan.min_radius);
  plan.k = polygon_vertices(r_max, max_error / 2);
  const double magnitude = (reach.extent + r_max) / plan.grid;
  if (magnitude > kMaxGridUnits) {
    throw InvalidInput("coordinates too large for the requested precision (more than 10^18 " +
                       std::string("grid steps of ") + std::to_string(plan.grid) + " mm)");
  }
  // Double arithmetic on coordinates (a disk vertex r·(cos, sin) added to a sample, the
  // simplification's chord distances, Clipper's arc points) errs by at most a few ulps of the
  // largest magnitude per operation, fewer than 16 along any chain here (each coordinate ~4
  // operations, the distance's hypot and the radius term on top): that much is added too.
  const double arithmetic = up(16.0 * std::ldexp(reach.extent + r_max, -52));
  const double widened = std::max(0.0, up(plan.min_radius - reach.r_min));
  const double half_diagonal = up(up(std::numbers::sqrt2 / 2) * plan.grid);
  // Each union (ink_union.hpp): Clipper's doubles in its intersection points and its sweep's
  // decisions on rounded x.
  const double per_union = up(sum_up({ink_detail::clipper_union_arithmetic(magnitude),
                                      ink_detail::clipper_union_sweep(magnitude)}) *
                              plan.grid);
  plan.final_union = sum_up({half_diagonal, per_union});
  plan.hull_bound = sum_up({disk_sagitta_up(r_max, plan.k), plan.tau, up(2 * half_diagonal),
                            arithmetic, per_union, widened});
  // Clipper rounds the number of arc steps, so a last chord may span 1.5 nominal steps: its
  // sagitta is at most 2.25 times the arc tolerance.
  plan.arc_tolerance = max_error / 2 / 2.25;
  plan.offset_bound =
      sum_up({max_error / 2, plan.tau, up(kOffsetRoundings * half_diagonal), arithmetic,
              clipper_turning(r_max, plan.arc_tolerance), up(kOffsetUnions * per_union), widened});
  return plan;
}

} // namespace ink_detail

namespace {

// The k-gon inscribed in a sample's disk, rounded onto the grid.
class DiskPolygon {
 public:
  DiskPolygon(std::size_t k, Grid grid) : grid_(grid), cos_(k), sin_(k) {
    for (std::size_t i = 0; i < k; ++i) {
      const double a = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(k);
      cos_[i] = std::cos(a);
      sin_[i] = std::sin(a);
    }
  }
  void add(Path& path, const InkSample& s) const {
    for (std::size_t i = 0; i < cos_.size(); ++i) {
      path.push_back(
          {grid_.round(s.x + s.radius * cos_[i]), grid_.round(s.y + s.radius * sin_[i])});
    }
  }

 private:
  Grid grid_;
  std::vector<double> cos_;
  std::vector<double> sin_;
};

// One radius: Clipper's own offset of the open polyline with round joins and ends (arc vertices
// on the circle), the same region as the union of the hulls.
void add_offset(const std::vector<InkSample>& kept, const Plan& plan, Grid grid, Paths& pieces) {
  ClipperLib::ClipperOffset offsetter;
  offsetter.ArcTolerance = plan.arc_tolerance * grid.scale;
  Path line;
  line.reserve(kept.size());
  for (const auto& x : kept) line.push_back({grid.round(x.x), grid.round(x.y)});
  offsetter.AddPath(line, ClipperLib::jtRound, ClipperLib::etOpenRound);
  Paths outline;
  offsetter.Execute(outline, kept.front().radius * grid.scale);
  pieces.insert(pieces.end(), outline.begin(), outline.end());
}

} // namespace

namespace ink_detail {

ChunkPieces build_chunk(const InkSample* first, std::size_t count, const Plan& plan) {
  const Grid grid{1.0 / plan.grid};
  std::vector<InkSample> widened(first, first + count);
  for (InkSample& x : widened) x.radius = std::max(x.radius, plan.min_radius);
  const std::vector<InkSample> kept = simplify(widened, plan.tau);
  const bool constant_radius = std::all_of(kept.begin(), kept.end(), [&](const InkSample& x) {
    return x.radius == kept.front().radius;
  });
  ChunkPieces out;
  out.grid = plan.grid;
  if (constant_radius && kept.size() > 1) {
    out.offset = true;
    add_offset(kept, plan, grid, out.paths);
  } else {
    out.k = plan.k;
    const DiskPolygon disk(plan.k, grid);
    if (kept.size() == 1) {
      Path one;
      disk.add(one, kept.front());
      out.paths.push_back(convex_hull(std::move(one)));
    }
    // Varying radius: the hull of the two end disks per segment.
    for (std::size_t i = 0; i + 1 < kept.size(); ++i) {
      Path both;
      both.reserve(2 * plan.k);
      disk.add(both, kept[i]);
      disk.add(both, kept[i + 1]);
      out.paths.push_back(convex_hull(std::move(both)));
    }
  }
  out.pinch = clipper_pinch_factor(out.paths);
  return out;
}

bool same_pieces(const ChunkPieces& pieces, const Plan& plan) {
  return pieces.grid == plan.grid && (pieces.offset || pieces.k == plan.k);
}

InkPolygon assemble(const std::vector<const ChunkPieces*>& chunks, const Plan& plan) {
  FedUnion fed;
  return assemble(chunks, plan, fed, 0);
}

InkPolygon assemble(const std::vector<const ChunkPieces*>& chunks, const Plan& plan, FedUnion& fed,
                    std::size_t fed_chunks) {
  InkPolygon result;
  result.grid = plan.grid;
  result.disk_vertices = plan.k;
  double pinch = 1.0;
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    const ChunkPieces& chunk = *chunks[c];
    const double bound = chunk.offset ? plan.offset_bound : plan.hull_bound;
    result.hausdorff_bound = std::max(result.hausdorff_bound, bound);
    pinch = std::max(pinch, chunk.pinch);
    if (c >= fed_chunks) fed.add(chunk.paths);
  }
  // Sharp piece corners (a disk far below the grid's scale beside a large one) let the final,
  // StrictlySimple union pinch off more than its sweep term (ink_union.hpp).
  if (pinch > 1) {
    result.hausdorff_bound = up(result.hausdorff_bound + up((pinch - 1) * plan.final_union));
  }
  ClipperLib::PolyTree tree;
  if (!fed.execute(tree)) {
    throw InvalidInput("the union of the pen hulls failed (coordinates out of range)");
  }
  for (const ClipperLib::PolyNode* node : tree.Childs) collect(*node, result.grid, result.region);
  normalize_orientation(result.region);
  return result;
}

} // namespace ink_detail

InkPolygon ink_polygon(const std::vector<std::vector<InkSample>>& strokes,
                       const InkOptions& options) {
  std::size_t total = 0;
  for (const auto& stroke : strokes) total += stroke.size();
  const double max_error = ink_detail::checked_max_error(options, total);
  const Plan plan = ink_detail::plan_for(max_error, ink_detail::checked_reach(strokes));
  std::vector<ink_detail::ChunkPieces> chunks;
  for (const auto& samples : strokes) {
    for (std::size_t c = 0; c < ink_detail::chunk_count(samples.size()); ++c) {
      const std::size_t first = c * ink_detail::kChunkSegments;
      const std::size_t count = std::min(ink_detail::kChunkSegments + 1, samples.size() - first);
      chunks.push_back(ink_detail::build_chunk(samples.data() + first, count, plan));
    }
  }
  std::vector<const ink_detail::ChunkPieces*> all;
  all.reserve(chunks.size());
  for (const auto& chunk : chunks) all.push_back(&chunk);
  return ink_detail::assemble(all, plan);
}

InkPolygon ink_polygon(const std::vector<InkSample>& samples, const InkOptions& options) {
  return ink_polygon(std::vector<std::vector<InkSample>>{samples}, options);
}

InkPolygon ink_polygon(const Stroke& stroke, const InkOptions& options) {
  return ink_polygon(ink_samples(stroke, options), options);
}

} // namespace penshape
