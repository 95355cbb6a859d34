// Whether a certified arrow is a plausible snap (fit_arrow.hpp, arrow_implausibility): how tight
// it fits, the tracing, the bends of its shaft and the shape of its head.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "recognize/arrow/arrow_limits.hpp"
#include "recognize/arrow/fit_arrow.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {
namespace {

enum class PieceRole { kShaft, kHead, kNone };

// How far a stroke strays from the chord between a and b.
double deviation(const std::vector<PointD>& piece, PointD a, PointD b) {
  double far = 0.0;
  for (const PointD& p : piece) far = std::max(far, segment_distance(p, a, b));
  return far;
}

// Whether a stroke runs along the shaft from tail to tip for at least kMinShaftSpan of it: a
// loose epsilon lets a short stroke across the shaft (the bar of an A) lie within it.
bool spans_shaft(const std::vector<PointD>& piece, PointD tail, PointD tip) {
  const PointD axis = tip - tail;
  const double len2 = dot(axis, axis);
  if (len2 <= 0.0) return false;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const PointD& p : piece) {
    const double t = dot(p - tail, axis) / len2;
    lo = std::min(lo, t), hi = std::max(hi, t);
  }
  return hi - lo >= arrow_rules().min_shaft_span;
}

// Which part of an arrow (vertices v: tail, tip, barb ends) one stroke draws: the shaft when it
// lies along the shaft and starts or ends at the tail; the head when it lies along the barbs and
// both its ends are at the tip or a barb's end, not both at one (a chevron that turns at the
// tip, or one barb).
PieceRole piece_role(const std::vector<PointD>& piece, const std::vector<PointD>& shaft,
                     const std::vector<PointD>& head, const std::vector<PointD>& v,
                     double epsilon) {
  bool on_shaft = true, on_head = true;
  for (const PointD& p : resample(piece, kPieceSamples)) {
    on_shaft = on_shaft && polyline_distance(p, shaft) <= epsilon;
    on_head = on_head && polyline_distance(p, head) <= epsilon;
  }
  auto near = [&](PointD p, std::size_t k) { return distance(p, v[k]) <= epsilon; };
  const PointD a = piece.front(), b = piece.back();
  if (on_shaft && !on_head && (near(a, 0) || near(b, 0)) &&
      spans_shaft(piece, v[0], shaft.back())) {
    return PieceRole::kShaft;
  }
  if (on_head && !on_shaft) {
    for (const std::size_t i : {std::size_t{1}, std::size_t{2}, std::size_t{3}}) {
      for (const std::size_t j : {std::size_t{1}, std::size_t{2}, std::size_t{3}}) {
        if (i == j || !near(a, i) || !near(b, j)) continue;
        // A head drawn from barb end to barb end turns at the tip: the stroke itself stands out
        // from its chord by more than epsilon (else a straight stroke passes for a head, the
        // fitted tip floating within a loose epsilon of it).
        // And it turns there: it passes within epsilon of the tip.
        const bool turns_at_tip =
            deviation(piece, a, b) > epsilon && polyline_distance(v[1], piece) <= epsilon;
        if (i != 1 && j != 1 && !turns_at_tip) continue;
        return PieceRole::kHead;
      }
    }
  }
  return PieceRole::kNone;
}

// Why a bent shaft tail -> bends -> tip is not plausible (empty when it is).
std::string bend_implausibility(PointD tail, PointD tip, const std::vector<PointD>& bends,
                                double epsilon) {
  const std::vector<PointD> shaft = shaft_path(tail, tip, 0.0, bends);
  for (std::size_t i = 1; i + 1 < shaft.size(); ++i) {
    if (segment_distance(shaft[i], shaft[i - 1], shaft[i + 1]) < kMinBendOffset * epsilon) {
      return "a shaft bend is within epsilon / 2 of its neighbours' chord (not a bend)";
    }
    if (angle_between(shaft[i] - shaft[i - 1], shaft[i + 1] - shaft[i]) > kMaxBendTurn) {
      return "the shaft turns by more than 100 degrees at a bend (it doubles back)";
    }
  }
  return {};
}

// Why a shaft that stops short of the tip is not plausible (empty when it is): its head is drawn
// apart (a shaft stroke, a head stroke); the gap runs forward from the shaft's end and is aimed at
// the tip: within max_gap_aim of the shaft's direction, or the tip within epsilon / 2 of the
// shaft's line (kMinBendOffset: the shaft's end and the tip are each only known within epsilon,
// so a short gap's angle says nothing); and it is at most max_gap_barb mean barbs long (else a
// dash beside a chevron).
std::string gap_implausibility(const ShapeParams& p, double epsilon, bool head_apart) {
  if (!p.shaft_end) return {};
  if (!head_apart) return "a shaft stops short of its tip only when the head is drawn apart";
  const std::vector<PointD>& v = p.vertices;
  const PointD end = *p.shaft_end;
  const PointD along = end - (p.shaft_bends.empty() ? v[0] : p.shaft_bends.back());
  const PointD gap = v[1] - end;
  const double off_line = std::abs(cross(along, gap)) / norm(along);
  const bool aimed = angle_between(along, gap) <= arrow_rules().max_gap_aim ||
                     (dot(along, gap) > 0.0 && off_line <= kMinBendOffset * epsilon);
  if (norm(gap) > 0.0 && !aimed) {
    return "a shaft that stops short is not aimed at the tip (more than 12 degrees off)";
  }
  const double barb = 0.5 * (distance(v[2], v[1]) + distance(v[3], v[1]));
  if (norm(gap) > arrow_rules().max_gap_barb * barb) {
    return "a shaft stops short of its tip by more than 1.3 barbs";
  }
  return {};
}

} // namespace

bool head_drawn_apart(const Fit& f, const UnionStroke& u, double epsilon) {
  if (f.shape != ShapeClass::kArrow || u.pieces.size() < 2) return false;
  const std::vector<PointD>& v = f.params.vertices;
  const std::vector<PointD> shaft = shaft_path(v[0], f.params.shaft_end.value_or(v[1]),
                                               f.params.shaft_bulge, f.params.shaft_bends);
  const std::vector<PointD> head{v[2], v[1], v[3]};
  // Each barb ends where a head stroke ends: a barb hidden in the shaft's ink (short, near the
  // shaft within a loose epsilon) is no barb drawn.
  bool shaft_seen = false, barb_drawn[2] = {false, false};
  for (const std::vector<PointD>& piece : u.pieces) {
    switch (piece_role(piece, shaft, head, v, epsilon)) {
      case PieceRole::kShaft:
        shaft_seen = true;
        break;
      case PieceRole::kHead:
        for (const std::size_t k : {std::size_t{2}, std::size_t{3}}) {
          const bool ends_there =
              distance(piece.front(), v[k]) <= epsilon || distance(piece.back(), v[k]) <= epsilon;
          barb_drawn[k - 2] = barb_drawn[k - 2] || ends_there;
        }
        break;
      case PieceRole::kNone:
        return false;
    }
  }
  return shaft_seen && barb_drawn[0] && barb_drawn[1];
}

std::string arrow_implausibility(const Fit& f, const Certificate& c, double drawn_length,
                                 bool head_apart) {
  const std::vector<PointD>& v = f.params.vertices;
  const double eps = c.epsilon;
  if (!head_apart && c.bound > kStraightFraction * eps) {
    return "an arrow is straight pieces: it must fit within 0.6 epsilon";
  }
  const double max_barb = head_apart ? arrow_rules().max_apart_barb : kMaxBarbFraction;
  if (drawn_length > kMaxTracingArrow * f.clean.length()) {
    return "the strokes are much longer than the arrow (traced over, a scribble or writing)";
  }
  const double bulge = f.params.shaft_bulge;
  const std::vector<PointD>& bends = f.params.shaft_bends;
  const PointD shaft_stop = f.params.shaft_end.value_or(v[1]);
  // Barbs are measured against the shaft as drawn: a bent or curved shaft's path, not its chord.
  const double shaft =
      std::max(distance(v[0], v[1]), path_length(shaft_path(v[0], shaft_stop, bulge, bends)));
  if (std::string why = bend_implausibility(v[0], shaft_stop, bends, eps); !why.empty()) return why;
  if (std::string why = gap_implausibility(f.params, eps, head_apart); !why.empty()) return why;
  auto head_ok = [&](PointD head, PointD back, PointD b1, PointD b2) -> std::string {
    for (const PointD& b : {b1, b2}) {
      const double len = distance(b, head);
      if (len < eps) return "a barb is shorter than epsilon";
      if (len > max_barb * shaft) return "a barb is longer than 0.8 shafts (2 when drawn apart)";
      // A bent shaft's end piece is fitted to the ink it follows, so ink along the shaft near
      // the head can pass for a barb: its barbs' ends must leave the end piece's line by
      // epsilon / 2 (as find_barbs asks of a barb, and a polyline of its corners).
      if (!bends.empty() && std::abs(cross(back, b - head)) < kMinBendOffset * eps * norm(back)) {
        return "a barb's end is within epsilon / 2 of a bent shaft's end piece";
      }
      const double angle = angle_between(back, b - head);
      if (angle < kMinHeadAngle || angle > kMaxHeadAngle) {
        return "a barb leaves the shaft at less than 10 or more than 80 degrees";
      }
    }
    if (cross(back, b1 - head) * cross(back, b2 - head) >= 0) {
      return "both barbs lie on the same side of the shaft";
    }
    // A bent shaft's last piece turns freely with its bend: it must lead into the head, along
    // the head's axis (the barbs' bisector), or a "barb" may be the drawing's own continuation.
    const double skew =
        0.5 * std::abs(angle_between(back, b1 - head) - angle_between(back, b2 - head));
    if (!bends.empty() && skew > kMaxBentHeadSkew) {
      return "a bent shaft's last piece is more than 25 degrees off the head's axis";
    }
    return {};
  };
  std::string why = head_ok(v[1], shaft_back(v[0], v[1], bulge, bends), v[2], v[3]);
  if (why.empty() && f.shape == ShapeClass::kDoubleArrow) {
    why = head_ok(v[0], shaft_forward(v[0], v[1], bulge, bends), v[4], v[5]);
  }
  return why;
}

} // namespace penshape::recognize_detail
