// Recognition of several strokes as one drawing (group_recognize.hpp, "Recognizing a union"),
// and arrows for any number of strokes.
#include "recognize/group/group_classifier.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "recognize/arrow/arrow_limits.hpp"
#include "recognize/arrow/fit_arrow.hpp"
#include "recognize/classify/classifier.hpp"
#include "recognize/fitting/dot.hpp"
#include "recognize/group/stroke_chain.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

double rank_of(const Candidate& c, const Fit& f, double epsilon) {
  return (c.certificate.bound + kRmsWeight * c.rms) / epsilon +
         kPricePerParameter * degrees_of_freedom(f);
}

void sort_scored(std::vector<Scored>& scored) {
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) {
    if (a.snap != b.snap) return a.snap;
    return a.rank < b.rank;
  });
}

// The tidiest shape wins: when an arrow with a straight or curved shaft is a snap within 0.6
// epsilon (as every arrow must fit unless its head is drawn apart), no arrow of the same class
// with a bent shaft is one. A looser one leaves the ranks to decide: a head drawn apart excuses
// a loose head, not a shaft that misses its bend. Likewise, when an arrow whose shaft runs to its
// tip is a snap, no arrow whose shaft stops short is one (the gap only rescues a drawing whose
// joined arrow does not certify).
void prefer_unbent_shafts(std::vector<Scored>& arrows, double epsilon) {
  const bool joined_snaps = std::any_of(arrows.begin(), arrows.end(), [](const Scored& a) {
    return a.snap && !a.fit.params.shaft_end;
  });
  for (Scored& a : arrows) {
    if (joined_snaps && a.snap && a.fit.params.shaft_end) {
      a.snap = false;
      a.candidate.rejected = "an arrow whose shaft runs to its tip certifies (the tidier shape)";
    }
  }
  for (const Scored& a : arrows) {
    if (!a.snap || !a.fit.params.shaft_bends.empty()) continue;
    if (a.candidate.certificate.bound > kStraightFraction * epsilon) continue;
    for (Scored& b : arrows) {
      if (b.snap && b.fit.shape == a.fit.shape && !b.fit.params.shaft_bends.empty()) {
        b.snap = false;
        b.candidate.rejected = "a straight or curved shaft certifies (the tidier shape wins)";
      }
    }
  }
}

// Arrows fitted at `scale` epsilon (see score_each_arrow), each certified and checked for
// plausibility at that scale (a certificate within scale * epsilon is one within epsilon);
// ranked against the other families at epsilon.
std::vector<Scored> score_arrows_at(const UnionStroke& u, const std::vector<PointD>& cloud,
                                    double drawn_length, double epsilon, double scale,
                                    ArrowSearch search, double pen_radius, double rank_to_beat) {
  const double e = scale * epsilon;
  std::vector<Scored> out;
  for (Fit& f : fit_arrows(u, e, rank_to_beat, search)) {
    Scored sc;
    Candidate& c = sc.candidate;
    c.shape = f.shape;
    c.params = f.params;
    c.clean = f.clean.path;
    if (f.fit_error <= kCertifyIfBelow * e) {
      c.certificate = certify_union(u, f.clean, e, pen_radius);
    } else {
      c.certificate.epsilon = e;
      c.certificate.pen_radius = pen_radius;
      c.certificate.bound = f.fit_error;
    }
    if (c.certificate.certified) {
      c.rejected = arrow_implausibility(f, c.certificate, drawn_length, head_drawn_apart(f, u, e));
    }
    // Within scale * epsilon is within epsilon; a refused fit keeps the scale it was refused at.
    if (c.certificate.certified) c.certificate.epsilon = epsilon;
    c.rms = rms_distance(cloud, f.clean);
    sc.rank = rank_of(c, f, epsilon);
    sc.snap = c.certificate.certified && c.rejected.empty();
    sc.fit = std::move(f);
    out.push_back(std::move(sc));
  }
  return out;
}

// Arrows that might beat a snap of rank `rank_to_beat` (infinite: none), each certified and
// checked for plausibility on its own (before prefer_unbent_shafts compares them), within the
// arrows' share of epsilon (ArrowRules::tolerance_share). A head is found and judged at that
// scale, which follows the whole drawing, so a long shaft's small head (barbs shorter than it)
// is no head there: when no arrow snaps, arrows with a straight shaft are sought again at the
// finer scales of kArrowHeadScales, where the whole arrow must then certify (the shaft as well
// as the head) and pass every rule. Curved and bent shafts are sought at the first scale only
// (they cost the most).
std::vector<Scored> score_each_arrow(const UnionStroke& u, const std::vector<PointD>& cloud,
                                     double drawn_length, double epsilon, double pen_radius,
                                     double rank_to_beat) {
  std::vector<Scored> out;
  for (const double scale : kArrowHeadScales) {
    const bool first = scale == kArrowHeadScales[0];
    std::vector<Scored> at = score_arrows_at(
        u, cloud, drawn_length, epsilon, arrow_rules().tolerance_share * scale,
        first ? ArrowSearch::kAll : ArrowSearch::kStraightShafts, pen_radius, rank_to_beat);
    const bool snaps = std::any_of(at.begin(), at.end(), [](const Scored& a) { return a.snap; });
    if (first || snaps) {
      out.insert(out.end(), std::make_move_iterator(at.begin()), std::make_move_iterator(at.end()));
    }
    if (snaps || !arrow_rules().finer_head_scales) break;
  }
  return out;
}

// Arrows that might beat a snap of rank `rank_to_beat` (infinite: none).
std::vector<Scored> score_arrows(const UnionStroke& u, const std::vector<PointD>& cloud,
                                 double drawn_length, double epsilon, double pen_radius,
                                 double rank_to_beat) {
  std::vector<Scored> out =
      score_each_arrow(u, cloud, drawn_length, epsilon, pen_radius, rank_to_beat);
  prefer_unbent_shafts(out, epsilon);
  return out;
}

// Whether a single arrow certifies on the union and is plausible. Every single arrow
// recognize_union_detail can end with (its winner, or an alternative keep_union reads the union
// as) is one: fit_arrows without a rank to beat fits each arrow it fits with one (a rank only
// stops it early), and an arrow's certificate and plausibility are its own; the other families
// and prefer_unbent_shafts only take snaps away.
bool a_single_arrow_certifies(const UnionStroke& u, const std::vector<PointD>& cloud,
                              double drawn_length, const ToleranceChoice& tol) {
  const std::vector<Scored> arrows =
      score_each_arrow(u, cloud, drawn_length, tol.epsilon, tol.pen_radius, INFINITY);
  return std::any_of(arrows.begin(), arrows.end(),
                     [](const Scored& a) { return a.fit.shape == ShapeClass::kArrow && a.snap; });
}

// The width of a closed shape (polygons: the least over the sides of the farthest vertex from
// the side's line, exact for convex ones); infinite for open shapes.
double closed_width(const Fit& f) {
  if (f.shape == ShapeClass::kCircle) return 2.0 * f.params.radius_x;
  if (f.shape == ShapeClass::kEllipse) return 2.0 * std::min(f.params.radius_x, f.params.radius_y);
  if (!convex_polygon(f.shape)) return INFINITY;
  const std::vector<PointD>& v = f.params.vertices;
  double width = INFINITY;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const PointD a = v[i], b = v[(i + 1) % v.size()];
    const double side = distance(a, b);
    if (side <= 0.0) continue;
    double far = 0.0;
    for (const PointD& p : v) far = std::max(far, std::abs(cross(b - a, p - a)) / side);
    width = std::min(width, far);
  }
  return width;
}

// Several strokes: fitted on their chain, then the snaps certified on the union, best rank
// first, until one passes (the others after it keep their chain-screening certificate).
std::vector<Scored> score_chain(const UnionStroke& u, const PreparedStroke& s,
                                const RecognizerConfig& config, double epsilon, double pen_radius) {
  std::vector<Scored> scored =
      evaluate(s, fit_all(s, config, epsilon), epsilon, pen_radius, config);
  for (Scored& sc : scored) {
    if (!sc.snap) break;
    if (closed_width(sc.fit) < kMinClosedWidth * epsilon) {
      sc.snap = false;
      sc.candidate.rejected =
          "a closed shape of several strokes narrower than 2 epsilon (strokes side by side)";
      continue;
    }
    sc.candidate.certificate = certify_union(u, sc.fit.clean, epsilon, pen_radius);
    sc.snap = sc.candidate.certificate.certified;
    if (sc.snap) break;
  }
  return scored;
}

// The rank an arrow must beat to win over a snap: the snap's rank, or none at all (0) for a
// closed shape at least 2 epsilon wide. An arrow with a straight shaft is three straight pieces
// from one point (its tip); drawn ink within 0.6 epsilon of them lies in three strips 1.2
// epsilon wide meeting there, and a closed outline in such strips either hugs one strip
// (narrower than 2 epsilon) or crosses between strips where no ink is drawn. So such an outline
// never certifies as a straight arrow, and the closed reading is kept over bent or curved ones.
double rank_for_arrows_to_beat(ShapeClass shape, const ShapeParams& params, double rank,
                               double epsilon) {
  Fit f;
  f.shape = shape;
  f.params = params;
  const double width = closed_width(f);
  return std::isfinite(width) && width >= kMinClosedWidth * epsilon ? 0.0 : rank;
}

// The winner of one stroke's own recognition as a Scored entry, to compete with the arrows.
double recognition_rank(const Recognition& r) {
  if (r.shape == ShapeClass::kFreeform) return INFINITY;
  Fit f;
  f.shape = r.shape;
  f.params = r.params;
  return (r.certificate.bound + kRmsWeight * r.rms) / r.epsilon +
         kPricePerParameter * degrees_of_freedom(f);
}

// Nothing certifies on the union: freeform at its tolerance.
UnionRecognition freeform_union(const ToleranceChoice& tol) {
  UnionRecognition out;
  out.rank = INFINITY;
  out.recognition.epsilon = tol.epsilon;
  out.recognition.pen_radius = tol.pen_radius;
  out.recognition.certificate.epsilon = tol.epsilon;
  out.recognition.certificate.pen_radius = tol.pen_radius;
  return out;
}

// A dot alone is a dot; a dot is never part of a shape of several strokes (freeform).
UnionRecognition dot_union(std::span<const StrokeInput> strokes, const RecognizerConfig& config,
                           const ToleranceChoice& tol) {
  if (strokes.size() > 1) return freeform_union(tol);
  UnionRecognition out;
  out.recognition = recognize(strokes.front(), config);
  out.strokes.pieces = {{out.recognition.params.center}};
  out.rank = 0.0;
  return out;
}

// Each stroke resampled as a chain's fit points are (kFitPoints over the drawn length), in its own
// drawing order: the chain may run a stroke backwards to shorten its jumps.
std::vector<std::vector<PointD>> pieces_as_drawn(const std::vector<std::vector<PointD>>& paths,
                                                 double drawn_length) {
  std::vector<std::vector<PointD>> out;
  out.reserve(paths.size());
  for (const std::vector<PointD>& p : paths) {
    const double share = drawn_length > 0 ? path_length(p) / drawn_length : 0.0;
    const auto count = static_cast<std::size_t>(std::lround(share * kFitPoints));
    out.push_back(resample(p, std::max<std::size_t>(2, count)));
  }
  return out;
}

} // namespace

std::vector<PointD> distinct_path(const std::vector<StrokePoint>& samples) {
  std::vector<PointD> out;
  out.reserve(samples.size());
  for (const StrokePoint& s : samples) {
    const PointD q{s.x, s.y};
    if (out.empty() || !(out.back() == q)) out.push_back(q);
  }
  return out;
}

UnionRecognition recognize_union_detail(std::span<const StrokeInput> strokes,
                                        const RecognizerConfig& config_in, UnionUse use) {
  if (strokes.empty()) throw InvalidInput("recognize: no strokes");
  RecognizerConfig config = config_in;
  if (strokes.front().pen_radius > 0) config.pen_radius = strokes.front().pen_radius;
  std::vector<StrokePoint> all;
  std::vector<std::vector<PointD>> paths;
  double drawn_length = 0.0;
  for (const StrokeInput& st : strokes) {
    validate_samples(st.samples, config);
    all.insert(all.end(), st.samples.begin(), st.samples.end());
    paths.push_back(distinct_path(st.samples));
    drawn_length += path_length(paths.back());
  }
  const ToleranceChoice tol = choose_tolerance(all, config);
  const double tau = thinning_tolerance(config, tol.epsilon);
  UnionRecognition out;
  if (std::any_of(strokes.begin(), strokes.end(),
                  [](const StrokeInput& st) { return is_dot(st.samples); })) {
    return dot_union(strokes, config, tol);
  }
  out.strokes = prepare_union(paths, tau);
  const std::vector<PointD> cloud = cloud_of(out.strokes);
  // The other families are fitted only when the single arrow the caller keeps may come out.
  if (use == UnionUse::kSingleArrowOnly &&
      !a_single_arrow_certifies(out.strokes, cloud, drawn_length, tol)) {
    UnionRecognition none = freeform_union(tol);
    none.strokes = std::move(out.strokes);
    return none;
  }
  if (strokes.size() == 1) {
    out.recognition = recognize(strokes.front(), config);
    out.rank = recognition_rank(out.recognition);
    const double to_beat = rank_for_arrows_to_beat(out.recognition.shape, out.recognition.params,
                                                   out.rank, tol.epsilon);
    std::vector<Scored> arrows =
        score_arrows(out.strokes, cloud, drawn_length, tol.epsilon, tol.pen_radius, to_beat);
    sort_scored(arrows);
    if (!arrows.empty() && arrows.front().snap && arrows.front().rank < out.rank) {
      Recognition r = out.recognition;
      std::vector<Candidate> others = std::move(r.alternatives);
      if (r.shape != ShapeClass::kFreeform) {
        Candidate previous;
        previous.shape = r.shape;
        previous.params = r.params;
        previous.clean = r.clean;
        previous.certificate = r.certificate;
        previous.rms = r.rms;
        others.insert(others.begin(), std::move(previous));
      }
      out.rank = arrows.front().rank;
      out.recognition = choose(std::move(arrows), tol.epsilon, tol.pen_radius);
      out.recognition.alternatives.insert(out.recognition.alternatives.end(), others.begin(),
                                          others.end());
    } else {
      for (Scored& a : arrows) out.recognition.alternatives.push_back(std::move(a.candidate));
    }
    return out;
  }
  // The strokes read as one path (the single-stroke fitters see the union through it).
  PreparedStroke chain = prepare_points(chain_pieces(paths), tau);
  chain.pieces = paths.size();
  chain.piece_fit_points = pieces_as_drawn(paths, drawn_length);
  std::vector<Scored> scored = score_chain(out.strokes, chain, config, tol.epsilon, tol.pen_radius);
  // The best snap (score_chain may leave refused candidates before it).
  const auto best =
      std::find_if(scored.begin(), scored.end(), [](const Scored& sc) { return sc.snap; });
  const double to_beat =
      best == scored.end()
          ? INFINITY
          : rank_for_arrows_to_beat(best->fit.shape, best->fit.params, best->rank, tol.epsilon);
  for (Scored& a :
       score_arrows(out.strokes, cloud, drawn_length, tol.epsilon, tol.pen_radius, to_beat)) {
    scored.push_back(std::move(a));
  }
  sort_scored(scored);
  out.rank = !scored.empty() && scored.front().snap ? scored.front().rank : INFINITY;
  out.recognition = choose(std::move(scored), tol.epsilon, tol.pen_radius);
  return out;
}

std::optional<AlternativeReading> read_as_arrow(const Recognition& r) {
  return read_as(
      r, [](ShapeClass c) { return c == ShapeClass::kArrow || c == ShapeClass::kDoubleArrow; });
}

std::optional<AlternativeReading> read_as(const Recognition& r,
                                          const std::function<bool(ShapeClass)>& kind) {
  const auto& alt = r.alternatives;
  const auto found = std::find_if(alt.begin(), alt.end(), [&kind](const Candidate& c) {
    return kind(c.shape) && c.certificate.certified && c.rejected.empty();
  });
  if (found == alt.end()) return std::nullopt;
  AlternativeReading out;
  Recognition& a = out.recognition;
  a = r;
  a.alternatives.erase(a.alternatives.begin() + (found - alt.begin()));
  if (r.shape != ShapeClass::kFreeform) {
    a.alternatives.insert(a.alternatives.begin(),
                          Candidate{r.shape, r.params, r.clean, r.certificate, {}, r.rms});
  }
  a.shape = found->shape;
  a.params = found->params;
  a.clean = found->clean;
  a.certificate = found->certificate;
  a.rms = found->rms;
  a.confidence = std::clamp(1.0 - a.certificate.bound / (2.0 * a.epsilon), 0.0, 1.0);
  out.rank = recognition_rank(a);
  return out;
}

} // namespace penshape::recognize_detail

namespace penshape {

Recognition recognize_union(std::span<const StrokeInput> strokes, const RecognizerConfig& config) {
  return recognize_detail::recognize_union_detail(strokes, config).recognition;
}

} // namespace penshape
