#include "board_view.hpp"

#include <cmath>
#include <numbers>

#include "daemon_link.hpp"

namespace penshape::board {
namespace {

class Triangles {
 public:
  explicit Triangles(Rgb c) : color_{c.r, c.g, c.b, 255} {}
  void add(PointPx a, PointPx b, PointPx c) {
    for (const PointPx& p : {a, b, c}) vertices_.push_back({{p.x, p.y}, color_, {0, 0}});
  }
  void disk(PointPx c, float r) {
    constexpr int kSides = 20;
    for (int i = 0; i < kSides; ++i) {
      const double a0 = 2 * std::numbers::pi * i / kSides;
      const double a1 = 2 * std::numbers::pi * (i + 1) / kSides;
      add(c,
          {c.x + r * static_cast<float>(std::cos(a0)), c.y + r * static_cast<float>(std::sin(a0))},
          {c.x + r * static_cast<float>(std::cos(a1)), c.y + r * static_cast<float>(std::sin(a1))});
    }
  }
  void segment(PointPx a, PointPx b, float r) {
    const float dx = b.x - a.x;
    const float dy = b.y - a.y;
    const float len = std::hypot(dx, dy);
    if (len == 0) return;
    const PointPx n{-dy / len * r, dx / len * r};
    const PointPx a1{a.x + n.x, a.y + n.y}, a2{a.x - n.x, a.y - n.y};
    const PointPx b1{b.x + n.x, b.y + n.y}, b2{b.x - n.x, b.y - n.y};
    add(a1, b1, b2);
    add(a1, b2, a2);
  }
  // The polyline swept by a disk of radius r: segments plus a disk at every vertex.
  void ink(const std::vector<PointPx>& points, float r) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      disk(points[i], r);
      if (i + 1 < points.size()) segment(points[i], points[i + 1], r);
    }
  }
  void draw(SDL_Renderer* renderer) const {
    if (vertices_.empty()) return;
    SDL_RenderGeometry(renderer, nullptr, vertices_.data(), static_cast<int>(vertices_.size()),
                       nullptr, 0);
  }

 private:
  SDL_Color color_;
  std::vector<SDL_Vertex> vertices_;
};

PointPx px(const v1::Point& mm) {
  return {static_cast<float>(mm.x() * kPixelsPerMm), static_cast<float>(mm.y() * kPixelsPerMm)};
}

} // namespace

std::vector<PointPx> shape_polyline(const v1::Shape& shape) {
  std::vector<PointPx> out;
  constexpr int kSteps = 96;
  auto arc = [&](const v1::Point& c, double radius, double start, double sweep) {
    for (int i = 0; i <= kSteps; ++i) {
      const double a = start + sweep * i / kSteps;
      out.push_back({static_cast<float>((c.x() + radius * std::cos(a)) * kPixelsPerMm),
                     static_cast<float>((c.y() + radius * std::sin(a)) * kPixelsPerMm)});
    }
  };
  switch (shape.params_case()) {
    case v1::Shape::kVertices: {
      for (const auto& p : shape.vertices().vertices()) out.push_back(px(p));
      const bool open =
          shape.kind() == v1::SHAPE_KIND_SEGMENT || shape.kind() == v1::SHAPE_KIND_POLYLINE;
      if (!open && !out.empty()) out.push_back(out.front());
      break;
    }
    case v1::Shape::kCircle:
      arc(shape.circle().center(), shape.circle().radius(), 0, 2 * std::numbers::pi);
      break;
    case v1::Shape::kArc:
      arc(shape.arc().center(), shape.arc().radius(), shape.arc().start_rad(),
          shape.arc().sweep_rad());
      break;
    case v1::Shape::kEllipse: {
      const auto& e = shape.ellipse();
      const double c = std::cos(e.rotation_rad()), s = std::sin(e.rotation_rad());
      for (int i = 0; i <= kSteps; ++i) {
        const double t = 2 * std::numbers::pi * i / kSteps;
        const double x = e.semi_major() * std::cos(t), y = e.semi_minor() * std::sin(t);
        out.push_back({static_cast<float>((e.center().x() + c * x - s * y) * kPixelsPerMm),
                       static_cast<float>((e.center().y() + s * x + c * y) * kPixelsPerMm)});
      }
      break;
    }
    default:
      break;
  }
  return out;
}

void draw_board(SDL_Renderer* renderer, const BoardModel& model) {
  SDL_SetRenderDrawColor(renderer, kBackground.r, kBackground.g, kBackground.b, 255);
  SDL_RenderClear(renderer);
  Triangles faint(kFaintInk), guide(kPreviewInk), raw(kRawInk), shapes(kShapeInk);
  for (const BoardStroke& s : model.strokes()) {
    if (s.preview && !s.finished) guide.ink(shape_polyline(*s.preview), s.pen_radius_px / 3);
    if (s.snapped && s.shape) {
      faint.ink(s.points, s.pen_radius_px);
      shapes.ink(shape_polyline(*s.shape), s.pen_radius_px);
    } else if (s.held) { // held while the pen is down: the shape, following the pen
      faint.ink(s.points, s.pen_radius_px);
      shapes.ink(shape_polyline(*s.held), s.pen_radius_px);
    } else {
      raw.ink(s.points, s.pen_radius_px);
    }
  }
  faint.draw(renderer);
  guide.draw(renderer);
  raw.draw(renderer);
  shapes.draw(renderer);
}

bool save_screenshot(SDL_Renderer* renderer, const std::string& path) {
  int w = 0, h = 0;
  if (SDL_GetRendererOutputSize(renderer, &w, &h) != 0) return false;
  SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, w, h, 24, SDL_PIXELFORMAT_BGR24);
  if (surface == nullptr) return false;
  bool ok = SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_BGR24, surface->pixels,
                                 surface->pitch) == 0;
  ok = ok && SDL_SaveBMP(surface, path.c_str()) == 0;
  SDL_FreeSurface(surface);
  return ok;
}

} // namespace penshape::board
