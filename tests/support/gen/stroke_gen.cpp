// The stroke generator's drawings: which ideal path each kind is, how it is split into strokes,
// and its truth (see stroke_gen.hpp).
#include "stroke_gen.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <stdexcept>

#include "ideal_paths.hpp"
#include "pen_model.hpp"
#include "rng.hpp"
#include "stroke_measurements.hpp"

namespace penshape::gen {
namespace {

constexpr double kPi = std::numbers::pi;
using Paths = std::vector<std::vector<Pt>>;

// What one drawing is made of before the pen: its strokes' paths and the truth.
struct Plan {
  Paths paths;
  std::set<std::string> truth;
  bool is_shape = true;
  bool closed = false; // closed outlines get rounded corners and no hook
};

// Everything a kind's builder needs: the drawing's place, size and the random source.
struct Canvas {
  Pt centre;
  double size = 0.0; // the bounding-box diagonal aimed at
  Rng* rng = nullptr;
};

std::vector<Pt> polygon_at(const Canvas& c, const std::vector<Pt>& unit) {
  std::vector<Pt> out;
  out.reserve(unit.size());
  for (const Pt& p : unit) out.push_back({c.centre.x + c.size * p.x, c.centre.y + c.size * p.y});
  return out;
}

// A closed outline of these unit vertices, drawn from a random vertex in a random direction,
// with the measured closure gap (stopping short or overshooting).
Plan closed_plan(const Canvas& c, std::vector<Pt> unit, std::set<std::string> truth) {
  Rng& rng = *c.rng;
  if (rng.chance(0.5)) std::reverse(unit.begin(), unit.end());
  const double gap = std::fabs(rng.normal(measured::kClosureGapMean, measured::kClosureGapSd));
  const double signed_gap = (rng.chance(0.4) ? -1.0 : 1.0) * gap * c.size;
  const auto start = static_cast<std::size_t>(rng.integer(0, static_cast<int>(unit.size()) - 1));
  return {{closed_outline(polygon_at(c, unit), start, signed_gap)}, std::move(truth), true, true};
}

std::vector<Pt> rect_unit(double aspect, double rotation) {
  const double h = 1.0 / std::sqrt(1.0 + aspect * aspect), w = aspect * h; // diagonal 1
  std::vector<Pt> out;
  for (const Pt p : {Pt{-w / 2, -h / 2}, Pt{w / 2, -h / 2}, Pt{w / 2, h / 2}, Pt{-w / 2, h / 2}}) {
    out.push_back({p.x * std::cos(rotation) - p.y * std::sin(rotation),
                   p.x * std::sin(rotation) + p.y * std::cos(rotation)});
  }
  return out;
}

std::vector<Pt> regular_unit(int n, double rotation, double jitter, Rng& rng) {
  std::vector<Pt> out;
  for (int k = 0; k < n; ++k) {
    const double a = rotation + 2 * kPi * k / n + rng.normal(0, jitter);
    out.push_back({0.5 * std::cos(a), 0.5 * std::sin(a)});
  }
  return out;
}

Plan circle_like(const Canvas& c, double aspect, std::set<std::string> truth) {
  Rng& rng = *c.rng;
  const double b = 0.5 * c.size / std::sqrt(1.0 + aspect * aspect); // bounding-box diagonal
  const double gap = std::fabs(rng.normal(measured::kClosureGapMean, measured::kClosureGapSd));
  const double sweep = 2 * kPi + (rng.chance(0.5) ? 1 : -1) * gap * c.size / (aspect * b);
  const double dir = rng.chance(0.7) ? -1.0 : 1.0;
  const double rotation = aspect > 1.05 ? rng.uniform(-0.4, 0.4) : 0.0;
  return {{elliptic_arc(c.centre, aspect * b, b, rotation, rng.uniform(0, 2 * kPi), dir * sweep)},
          std::move(truth),
          true,
          false};
}

// The open corner or overshoot where two strokes of one shape meet.
Pt joint(Pt p, const Canvas& c) {
  return {p.x + c.rng->normal(0, 0.03 * c.size), p.y + c.rng->normal(0, 0.03 * c.size)};
}

// A closed polygon drawn as `pieces` strokes, each a run of its edges.
Plan pieces_plan(const Canvas& c, const std::vector<Pt>& unit, int pieces,
                 std::set<std::string> truth) {
  const std::vector<Pt> v = polygon_at(c, unit);
  const int n = static_cast<int>(v.size());
  Plan plan{{}, std::move(truth), true, false};
  for (int k = 0; k < pieces; ++k) {
    std::vector<Pt> path;
    for (int i = k * n / pieces; i <= (k + 1) * n / pieces; ++i)
      path.push_back(v[static_cast<std::size_t>(i % n)]);
    path.front() = joint(path.front(), c);
    path.back() = joint(path.back(), c);
    plan.paths.push_back(round_corners(path, measured::kCornerRounding * c.size));
  }
  return plan;
}

// An arrow from tail to tip; `strokes` 1 (shaft and head in one), 2 (shaft, head) or 3.
Plan arrow_plan(const Canvas& c, int strokes) {
  Rng& rng = *c.rng;
  const double angle = rng.uniform(-kPi, kPi), len = 0.9 * c.size;
  const Pt tail{c.centre.x - 0.5 * len * std::cos(angle), c.centre.y - 0.5 * len * std::sin(angle)};
  const Pt tip{c.centre.x + 0.5 * len * std::cos(angle), c.centre.y + 0.5 * len * std::sin(angle)};
  const double barb = rng.uniform(0.2, 0.35) * len, spread = rng.uniform(0.45, 0.7);
  auto barb_end = [&](double side) {
    const double a = angle + kPi + side * spread;
    return Pt{tip.x + barb * std::cos(a), tip.y + barb * std::sin(a)};
  };
  const Pt b1 = barb_end(1), b2 = barb_end(-1);
  Plan plan{{}, {"arrow"}, true, false};
  if (strokes == 1) plan.paths = {{tail, tip, b1, tip, b2}};
  if (strokes == 2) plan.paths = {{tail, tip}, {b1, joint(tip, c), b2}};
  if (strokes == 3) plan.paths = {{tail, tip}, {b1, joint(tip, c)}, {b2, joint(tip, c)}};
  return plan;
}

Plan open_plan(const Canvas& c, int vertices, std::set<std::string> truth) {
  Rng& rng = *c.rng;
  std::vector<Pt> v;
  double heading = rng.uniform(-kPi, kPi);
  Pt p{0, 0};
  for (int k = 0; k < vertices; ++k) {
    v.push_back(p);
    p = {p.x + std::cos(heading) / (vertices - 1), p.y + std::sin(heading) / (vertices - 1)};
    const double sign = rng.chance(0.5) ? 1 : -1; // drawn first, whatever the compiler
    heading += sign * rng.uniform(0.9, 2.2);
  }
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (const Pt& q : v) {
    xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x);
    ymin = std::min(ymin, q.y), ymax = std::max(ymax, q.y);
  }
  const double d = std::max(std::hypot(xmax - xmin, ymax - ymin), 1e-9);
  for (Pt& q : v) q = {(q.x - 0.5 * (xmin + xmax)) / d, (q.y - 0.5 * (ymin + ymax)) / d};
  return {{round_corners(polygon_at(c, v), 0.5 * measured::kCornerRounding * c.size)},
          std::move(truth),
          true,
          false};
}

using Builder = std::function<Plan(const Canvas&)>;

const std::map<std::string, Builder>& builders() {
  static const std::map<std::string, Builder> table{
      {"circle",
       [](const Canvas& c) {
         return circle_like(c, c.rng->uniform(1.0, 1.12), {"circle", "ellipse"});
       }},
      {"ellipse",
       [](const Canvas& c) { return circle_like(c, c.rng->uniform(1.6, 2.3), {"ellipse"}); }},
      {"rectangle",
       [](const Canvas& c) {
         return closed_plan(c, rect_unit(c.rng->uniform(1.5, 2.4), 0),
                            {"rectangle", "quadrilateral"});
       }},
      {"square",
       [](const Canvas& c) {
         return closed_plan(c, rect_unit(c.rng->uniform(0.95, 1.05), 0),
                            {"square", "rectangle", "quadrilateral"});
       }},
      {"diamond",
       [](const Canvas& c) {
         return closed_plan(c, rect_unit(c.rng->uniform(0.9, 1.1), kPi / 4),
                            {"diamond", "square", "quadrilateral"});
       }},
      {"triangle",
       [](const Canvas& c) {
         return closed_plan(c, regular_unit(3, c.rng->uniform(0, 2 * kPi), 0.15, *c.rng),
                            {"triangle"});
       }},
      {"pentagon",
       [](const Canvas& c) {
         return closed_plan(c, regular_unit(5, c.rng->uniform(0, 2 * kPi), 0.02, *c.rng),
                            {"regular_polygon"});
       }},
      {"hexagon",
       [](const Canvas& c) {
         return closed_plan(c, regular_unit(6, c.rng->uniform(0, 2 * kPi), 0.02, *c.rng),
                            {"regular_polygon"});
       }},
      {"line", [](const Canvas& c) { return open_plan(c, 2, {"segment"}); }},
      {"polyline",
       [](const Canvas& c) { return open_plan(c, c.rng->integer(3, 4), {"polyline"}); }},
      {"arc",
       [](const Canvas& c) {
         const double size = c.rng->uniform(1.6, 3.8); // drawn first, whatever the compiler
         const double sweep = size * (c.rng->chance(0.5) ? 1 : -1);
         return Plan{{elliptic_arc(c.centre, 0.45 * c.size, 0.45 * c.size, 0,
                                   c.rng->uniform(0, 2 * kPi), sweep)},
                     {"arc"},
                     true,
                     false};
       }},
      {"arrow1", [](const Canvas& c) { return arrow_plan(c, 1); }},
      {"arrow2", [](const Canvas& c) { return arrow_plan(c, 2); }},
      {"arrow3", [](const Canvas& c) { return arrow_plan(c, 3); }},
      {"rectangle2",
       [](const Canvas& c) {
         return pieces_plan(c, rect_unit(c.rng->uniform(1.4, 2.2), 0), 2,
                            {"rectangle", "quadrilateral"});
       }},
      {"rectangle4",
       [](const Canvas& c) {
         return pieces_plan(c, rect_unit(c.rng->uniform(1.4, 2.2), 0), 4,
                            {"rectangle", "quadrilateral"});
       }},
      {"triangle3",
       [](const Canvas& c) {
         return pieces_plan(c, regular_unit(3, c.rng->uniform(0, 2 * kPi), 0.1, *c.rng), 3,
                            {"triangle"});
       }},
      {"circle2",
       [](const Canvas& c) {
         const double from = c.rng->uniform(0, 2 * kPi), r = 0.35 * c.size;
         return Plan{{elliptic_arc(c.centre, r, r, 0, from, kPi + 0.1),
                      elliptic_arc(c.centre, r, r, 0, from + kPi, kPi + 0.1)},
                     {"circle", "ellipse"},
                     true,
                     false};
       }},
      {"scribble",
       [](const Canvas& c) {
         return Plan{{scribble(c.centre, 0.7 * c.size, c.rng->integer(8, 14), *c.rng)},
                     {"freeform"},
                     false,
                     false};
       }},
      {"spiral",
       [](const Canvas& c) {
         // Named: the order in which a call's arguments are evaluated differs between compilers.
         const bool clockwise = c.rng->chance(0.5);
         const double turns = c.rng->uniform(2.0, 3.5);
         return Plan{
             {spiral(c.centre, 0.4 * c.size, turns, clockwise)}, {"freeform"}, false, false};
       }},
      {"letter",
       [](const Canvas& c) {
         return Plan{{cursive_word({c.centre.x - 0.3 * c.size, c.centre.y + 0.2 * c.size},
                                   0.5 * c.size, 1, *c.rng)},
                     {"freeform"},
                     false,
                     false};
       }},
      {"word",
       [](const Canvas& c) {
         return Plan{{cursive_word({c.centre.x - 0.8 * c.size, c.centre.y}, 0.22 * c.size,
                                   c.rng->integer(3, 6), *c.rng)},
                     {"freeform"},
                     false,
                     false};
       }},
      {"dot",
       [](const Canvas& c) {
         return Plan{
             {{c.centre, {c.centre.x + c.rng->uniform(2, 4), c.centre.y + c.rng->uniform(1, 3)}}},
             {"freeform"},
             false,
             false};
       }},
  };
  return table;
}

// A logged stroke needs two distinct positions (a dot's samples may round to one pixel).
bool has_two_positions(const GenStroke& s) {
  for (const auto& p : s.points) {
    if (p.x != s.points.front().x || p.y != s.points.front().y) return true;
  }
  return false;
}

} // namespace

const char* to_string(Speed s) {
  return s == Speed::kSlow ? "slow" : s == Speed::kMedium ? "medium" : "fast";
}

const std::vector<std::string>& single_stroke_shape_kinds() {
  static const std::vector<std::string> kinds{"circle",  "ellipse",  "rectangle", "square",
                                              "diamond", "triangle", "pentagon",  "hexagon",
                                              "line",    "polyline", "arc",       "arrow1"};
  return kinds;
}
const std::vector<std::string>& multi_stroke_shape_kinds() {
  static const std::vector<std::string> kinds{"arrow2",     "arrow3",    "rectangle2",
                                              "rectangle4", "triangle3", "circle2"};
  return kinds;
}
const std::vector<std::string>& non_shape_kinds() {
  static const std::vector<std::string> kinds{"scribble", "spiral", "letter", "word", "dot"};
  return kinds;
}

struct StrokeGenerator::Impl {
  explicit Impl(std::uint64_t seed) : rng(seed) {}
  Rng rng;
};

StrokeGenerator::StrokeGenerator(std::uint64_t seed) : impl_(new Impl(seed)) {}
StrokeGenerator::~StrokeGenerator() { delete impl_; }

Drawing StrokeGenerator::draw(const std::string& kind, const DrawOptions& options) {
  const auto it = builders().find(kind);
  if (it == builders().end()) throw std::invalid_argument("stroke generator: unknown kind " + kind);
  Rng& rng = impl_->rng;
  Canvas canvas{{rng.uniform(150, 250), rng.uniform(150, 250)},
                options.scale * std::max(rng.normal(measured::kDiagonalMean, measured::kDiagonalSd),
                                         0.4 * measured::kDiagonalMean),
                &rng};
  Plan plan = it->second(canvas);
  Drawing out{kind, plan.truth, plan.is_shape, {}};
  const double speed = pen_speed(options.speed, rng);
  double t = 0.0;
  for (auto& path : plan.paths) {
    if (plan.closed) path = round_corners(path, measured::kCornerRounding * canvas.size);
    std::vector<Pt> dense = resample(path, 1.0);
    if (kind != "dot") {
      add_wobble(dense, wobble_rms(canvas.size, speed) * (plan.is_shape ? 1.0 : 0.5), canvas.size,
                 rng);
    }
    if (options.hooks && !plan.closed && kind != "dot" && rng.chance(measured::kHookShare))
      add_hook(dense, measured::kHookLength * canvas.size, rng);
    out.strokes.push_back(sample_pen(dense, speed, t, rng));
    t = out.strokes.back().points.back().t + rng.uniform(0.15, 0.45); // the pen is lifted
  }
  return out;
}

std::vector<CorpusEntry> single_stroke_corpus(std::uint64_t seed, int subjects, int per_kind) {
  std::vector<std::string> kinds = single_stroke_shape_kinds();
  kinds.insert(kinds.end(), non_shape_kinds().begin(), non_shape_kinds().end());
  std::vector<CorpusEntry> out;
  for (int s = 1; s <= subjects; ++s) {
    StrokeGenerator gen(seed * 1000 + static_cast<std::uint64_t>(s)); // one hand per subject
    for (const Speed speed : {Speed::kSlow, Speed::kMedium, Speed::kFast}) {
      for (const auto& kind : kinds) {
        for (int n = 1; n <= per_kind; ++n) {
          Drawing d = gen.draw(kind, {speed});
          while (!has_two_positions(d.strokes.front())) d = gen.draw(kind, {speed}); // a stroke
          out.push_back({s, speed, n, std::move(d)});
        }
      }
    }
  }
  return out;
}

} // namespace penshape::gen
