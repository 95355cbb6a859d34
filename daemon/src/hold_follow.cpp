// The held shape following the pen after a hold (hold_follow.hpp).
#include "hold_follow.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace penshape::daemon {
namespace {

// p -> pivot + M (p - pivot): M = [[a, b], [c, d]]. `scale` and `angle` describe M when it is a
// similarity (lengths and directions of curved params follow them).
struct Affine {
  PointMm pivot;
  double a = 1, b = 0, c = 0, d = 1;
  double scale = 1;
  double angle = 0;

  [[nodiscard]] PointMm apply(PointMm p) const {
    const double x = p.x - pivot.x;
    const double y = p.y - pivot.y;
    return {pivot.x + a * x + b * y, pivot.y + c * x + d * y};
  }
};

PointMm from_proto(const v1::Point& p) { return {p.x(), p.y()}; }

void map_point(const Affine& m, v1::Point* p) {
  const PointMm q = m.apply(from_proto(*p));
  p->set_x(q.x);
  p->set_y(q.y);
}

// The rotation and scaling about `pivot` that takes `from` to `to` (none when `from` is the pivot).
Affine similarity(PointMm pivot, PointMm from, PointMm to) {
  Affine m;
  m.pivot = pivot;
  const double fx = from.x - pivot.x;
  const double fy = from.y - pivot.y;
  const double norm = fx * fx + fy * fy;
  if (!(norm > 1e-18)) return m;
  const double tx = to.x - pivot.x;
  const double ty = to.y - pivot.y;
  // z = (to - pivot) / (from - pivot) as complex numbers.
  const double zr = (tx * fx + ty * fy) / norm;
  const double zi = (ty * fx - tx * fy) / norm;
  m.a = zr;
  m.b = -zi;
  m.c = zi;
  m.d = zr;
  m.scale = std::hypot(zr, zi);
  m.angle = std::atan2(zi, zr);
  return m;
}

double distance(PointMm a, PointMm b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The vertex nearest to p.
int nearest_vertex(const v1::VertexParams& v, PointMm p) {
  int best = 0;
  for (int i = 1; i < v.vertices_size(); ++i) {
    if (distance(from_proto(v.vertices(i)), p) < distance(from_proto(v.vertices(best)), p))
      best = i;
  }
  return best;
}

// A rectangle stretched along its own sides: the corner `moving` goes by `shift`, the opposite
// corner stays.
Affine rectangle_stretch(const v1::VertexParams& v, int moving, PointMm shift) {
  const int fixed = (moving + 2) % 4;
  const PointMm f = from_proto(v.vertices(fixed));
  const PointMm next = from_proto(v.vertices((fixed + 1) % 4));
  const PointMm prev = from_proto(v.vertices((fixed + 3) % 4));
  const double lu = distance(next, f);
  const double lw = distance(prev, f);
  Affine m;
  m.pivot = f;
  if (!(lu > 0 && lw > 0)) return m;
  const PointMm u{(next.x - f.x) / lu, (next.y - f.y) / lu};
  const PointMm w{(prev.x - f.x) / lw, (prev.y - f.y) / lw};
  const PointMm corner = from_proto(v.vertices(moving));
  const PointMm dd{corner.x + shift.x - f.x, corner.y + shift.y - f.y};
  const double su = (dd.x * u.x + dd.y * u.y) / lu;
  const double sw = (dd.x * w.x + dd.y * w.y) / lw;
  // M = su u u^T + sw w w^T (u and w are perpendicular: a rectangle).
  m.a = su * u.x * u.x + sw * w.x * w.x;
  m.b = su * u.x * u.y + sw * w.x * w.y;
  m.c = m.b;
  m.d = su * u.y * u.y + sw * w.y * w.y;
  m.scale = std::sqrt(std::abs(su * sw));
  return m;
}

// A shape of vertices: a segment's end nearest the hold moves with the tip; a rectangle's corner
// nearest the hold too (the opposite corner stays); any other is scaled and rotated about its
// first vertex, or about its vertices' mean when the pen holds nearer the first vertex than that
// (a closed shape drawn in one stroke ends where it began).
Affine vertices_map(const v1::Shape& s, PointMm hold, PointMm tip) {
  const v1::VertexParams& v = s.vertices();
  const PointMm shift{tip.x - hold.x, tip.y - hold.y};
  const int n = v.vertices_size();
  if (n == 0) return {};
  if (s.kind() == v1::SHAPE_KIND_RECTANGLE && n == 4) {
    return rectangle_stretch(v, nearest_vertex(v, hold), shift);
  }
  if (s.kind() == v1::SHAPE_KIND_SEGMENT && n == 2) {
    const int end = nearest_vertex(v, hold);
    const PointMm e = from_proto(v.vertices(end));
    return similarity(from_proto(v.vertices(1 - end)), e, {e.x + shift.x, e.y + shift.y});
  }
  const PointMm first = from_proto(v.vertices(0));
  PointMm mean;
  for (const v1::Point& p : v.vertices()) {
    mean.x += p.x() / n;
    mean.y += p.y() / n;
  }
  return similarity(distance(hold, first) < distance(hold, mean) ? mean : first, hold, tip);
}

// The map the pen's move from `hold` to `tip` gives the shape (see follow_shape).
Affine follow_map(const v1::Shape& s, PointMm hold, PointMm tip) {
  switch (s.params_case()) {
    case v1::Shape::kCircle: {
      const PointMm c = from_proto(s.circle().center());
      const double r = s.circle().radius();
      const double gain = distance(tip, c) - distance(hold, c);
      const double radius = std::max(r + gain, r * 1e-3);
      return similarity(c, {c.x + r, c.y}, {c.x + radius, c.y});
    }
    case v1::Shape::kEllipse:
      return similarity(from_proto(s.ellipse().center()), hold, tip);
    case v1::Shape::kArc: {
      const v1::ArcParams& a = s.arc();
      const PointMm start{a.center().x() + a.radius() * std::cos(a.start_rad()),
                          a.center().y() + a.radius() * std::sin(a.start_rad())};
      return similarity(start, hold, tip);
    }
    case v1::Shape::kArrow:
      return similarity(from_proto(s.arrow().tail()), hold, tip);
    case v1::Shape::kVertices:
      return vertices_map(s, hold, tip);
    default:
      return {};
  }
}

double angle_in(double a, double period) {
  a = std::fmod(a, period);
  return a < 0 ? a + period : a;
}

void map_params(const Affine& m, v1::Shape* s) {
  switch (s->params_case()) {
    case v1::Shape::kVertices:
      for (v1::Point& p : *s->mutable_vertices()->mutable_vertices()) map_point(m, &p);
      break;
    case v1::Shape::kCircle:
      map_point(m, s->mutable_circle()->mutable_center());
      s->mutable_circle()->set_radius(s->circle().radius() * m.scale);
      break;
    case v1::Shape::kEllipse: {
      v1::EllipseParams* e = s->mutable_ellipse();
      map_point(m, e->mutable_center());
      e->set_semi_major(e->semi_major() * m.scale);
      e->set_semi_minor(e->semi_minor() * m.scale);
      e->set_rotation_rad(angle_in(e->rotation_rad() + m.angle, std::numbers::pi));
      break;
    }
    case v1::Shape::kArc: {
      v1::ArcParams* a = s->mutable_arc();
      map_point(m, a->mutable_center());
      a->set_radius(a->radius() * m.scale);
      a->set_start_rad(a->start_rad() + m.angle);
      break;
    }
    case v1::Shape::kArrow: {
      v1::ArrowParams* a = s->mutable_arrow();
      map_point(m, a->mutable_tail());
      map_point(m, a->mutable_tip());
      for (v1::Point& p : *a->mutable_barbs()) map_point(m, &p);
      for (v1::Point& p : *a->mutable_tail_barbs()) map_point(m, &p);
      for (v1::Point& p : *a->mutable_shaft_bends()) map_point(m, &p);
      if (a->has_shaft_end()) map_point(m, a->mutable_shaft_end());
      a->set_shaft_bulge(a->shaft_bulge() * m.scale);
      break;
    }
    default:
      break;
  }
}

void map_clean_path(const Affine& m, v1::CurvedRing* ring) {
  for (v1::BoundaryPiece& piece : *ring->mutable_pieces()) {
    if (piece.has_segment()) {
      map_point(m, piece.mutable_segment()->mutable_start());
      map_point(m, piece.mutable_segment()->mutable_end());
    } else if (piece.has_arc()) {
      v1::CircularArc* a = piece.mutable_arc();
      map_point(m, a->mutable_start());
      map_point(m, a->mutable_end());
      map_point(m, a->mutable_center());
      a->set_radius(a->radius() * m.scale);
    }
  }
}

} // namespace

v1::Shape follow_shape(const v1::Shape& held, PointMm hold, PointMm tip) {
  v1::Shape out = held;
  const Affine m = follow_map(held, hold, tip);
  map_params(m, &out);
  map_clean_path(m, out.mutable_clean_path());
  if (out.has_certificate()) out.mutable_certificate()->set_scope("drawn_part+user_edit");
  return out;
}

} // namespace penshape::daemon
