// SVG path data to polylines. Curves are flattened with a piece count that bounds the distance:
// a uniform n-piece chord polyline of a curve B stays within max|B''| / (8 n^2) of it.
#include "path_data.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

#include "number_scanner.hpp"
#include "penshape/core/point_arithmetic.hpp"

namespace penshape::snap {
namespace {

constexpr std::size_t kMaxPieces = 1024;

std::size_t pieces_for(double second_derivative_bound, double flatness) {
  const double n = std::ceil(std::sqrt(second_derivative_bound / (8.0 * flatness)));
  return static_cast<std::size_t>(std::clamp(n, 1.0, static_cast<double>(kMaxPieces)));
}

void cubic(std::vector<PointD>& out, PointD p0, PointD p1, PointD p2, PointD p3, double flat) {
  // |B''| <= 6 max(|p0 - 2p1 + p2|, |p1 - 2p2 + p3|).
  const double m = 6 * std::max(norm(p0 - 2 * p1 + p2), norm(p1 - 2 * p2 + p3));
  const std::size_t n = pieces_for(m, flat);
  for (std::size_t i = 1; i <= n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n), u = 1 - t;
    out.push_back(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
  }
}

void quadratic(std::vector<PointD>& out, PointD p0, PointD p1, PointD p2, double flat) {
  const std::size_t n = pieces_for(2 * norm(p0 - 2 * p1 + p2), flat); // |B''| = 2|p0 - 2p1 + p2|
  for (std::size_t i = 1; i <= n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n), u = 1 - t;
    out.push_back(u * u * p0 + 2 * u * t * p1 + t * t * p2);
  }
}

double angle_between(PointD u, PointD v) {
  return std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
}

// Numbers each command takes per repeat.
std::size_t arity(char c) {
  switch (std::toupper(static_cast<unsigned char>(c))) {
    case 'M':
    case 'L':
    case 'T':
      return 2;
    case 'H':
    case 'V':
      return 1;
    case 'C':
      return 6;
    case 'S':
    case 'Q':
      return 4;
    case 'A':
      return 7;
    default:
      return 0;
  }
}

class PathParser {
 public:
  PathParser(std::string_view d, double flatness) : in_(d), flat_(flatness) {}

  std::vector<Subpath> run() {
    in_.skip_separators();
    while (!in_.done()) {
      const char c = in_.peek();
      if (!std::isalpha(static_cast<unsigned char>(c))) {
        fail("expected a command letter, found '" + std::string(1, c) + "'");
      }
      in_.take();
      if (arity(c) == 0 && std::toupper(static_cast<unsigned char>(c)) != 'Z') {
        fail("unknown command '" + std::string(1, c) + "'");
      }
      if (!started_ && std::toupper(static_cast<unsigned char>(c)) != 'M') {
        fail("path data must start with M, not '" + std::string(1, c) + "'");
      }
      started_ = true;
      command(c);
      in_.skip_separators();
    }
    finish();
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw PathDataError("path data at offset " + in_.where() + ": " + what);
  }

  double num() {
    in_.skip_separators();
    const auto v = in_.number();
    if (!v) fail("expected a number");
    return *v;
  }
  bool flag() {
    in_.skip_separators();
    const auto f = in_.flag();
    if (!f) fail("expected an arc flag 0 or 1");
    return *f;
  }

  void finish() {
    if (!cur_.points.empty()) out_.push_back(std::move(cur_));
    cur_ = {};
  }

  void line_to(PointD p) { cur_.points.push_back(p); }

  void command(char c) {
    const bool rel = std::islower(static_cast<unsigned char>(c)) != 0;
    const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (up == 'Z') {
      close();
      return;
    }
    bool first = true;
    do {
      one(up, rel, first);
      first = false;
      in_.skip_separators();
    } while (in_.at_number());
  }

  void close() {
    if (!cur_.points.empty()) {
      if (cur_.points.size() > 1 && cur_.points.back() == cur_.points.front())
        cur_.points.pop_back();
      cur_.closed = true;
      pos_ = start_;
      finish();
      reopen_ = true;
    }
    last_ctrl_ = pos_;
    last_cmd_ = 'Z';
  }

  void begin_if_needed() {
    // A drawing command after Z starts a new subpath at the closed one's start.
    if (reopen_) {
      cur_.points.push_back(pos_);
      reopen_ = false;
    }
  }

  void one(char up, bool rel, bool first) {
    const PointD o = rel ? pos_ : PointD{0, 0};
    PointD ctrl = pos_;
    if (up == 'M') {
      const PointD p = o + PointD{num(), num()};
      if (first) {
        finish();
        reopen_ = false;
        cur_.points.push_back(p);
        start_ = p;
      } else {
        line_to(p); // implicit lineto
      }
      pos_ = p;
    } else {
      begin_if_needed();
      switch (up) {
        case 'L':
          pos_ = o + PointD{num(), num()};
          line_to(pos_);
          break;
        case 'H':
          pos_ = {(rel ? pos_.x : 0) + num(), pos_.y};
          line_to(pos_);
          break;
        case 'V':
          pos_ = {pos_.x, (rel ? pos_.y : 0) + num()};
          line_to(pos_);
          break;
        case 'C': {
          const PointD p1 = o + PointD{num(), num()}, p2 = o + PointD{num(), num()};
          const PointD p3 = o + PointD{num(), num()};
          cubic(cur_.points, pos_, p1, p2, p3, flat_);
          ctrl = p2, pos_ = p3;
          break;
        }
        case 'S': {
          const PointD p1 = (last_cmd_ == 'C' || last_cmd_ == 'S') ? 2 * pos_ - last_ctrl_ : pos_;
          const PointD p2 = o + PointD{num(), num()}, p3 = o + PointD{num(), num()};
          cubic(cur_.points, pos_, p1, p2, p3, flat_);
          ctrl = p2, pos_ = p3;
          break;
        }
        case 'Q': {
          const PointD p1 = o + PointD{num(), num()}, p2 = o + PointD{num(), num()};
          quadratic(cur_.points, pos_, p1, p2, flat_);
          ctrl = p1, pos_ = p2;
          break;
        }
        case 'T': {
          const PointD p1 = (last_cmd_ == 'Q' || last_cmd_ == 'T') ? 2 * pos_ - last_ctrl_ : pos_;
          const PointD p2 = o + PointD{num(), num()};
          quadratic(cur_.points, pos_, p1, p2, flat_);
          ctrl = p1, pos_ = p2;
          break;
        }
        case 'A': {
          const double rx = num(), ry = num(), rot = num();
          const bool large = flag(), sweep = flag();
          const PointD p = o + PointD{num(), num()};
          for (const PointD& q : flatten_arc(pos_, rx, ry, rot, large, sweep, p, flat_)) {
            line_to(q);
          }
          pos_ = p;
          break;
        }
        default:
          break;
      }
    }
    last_ctrl_ = ctrl;
    last_cmd_ = up;
  }

  NumberScanner in_;
  double flat_;
  std::vector<Subpath> out_;
  Subpath cur_;
  PointD pos_{}, start_{}, last_ctrl_{};
  char last_cmd_ = 0;
  bool reopen_ = false;
  bool started_ = false; // a command was read (the first must be M)
};

} // namespace

std::vector<PointD> flatten_arc(PointD p0, double rx, double ry, double rot_deg, bool large,
                                bool sweep, PointD p1, double flat) {
  rx = std::abs(rx), ry = std::abs(ry);
  if (p0 == p1) return {};
  if (rx == 0 || ry == 0) return {p1}; // F.6.2: a straight line
  const double phi = rot_deg * std::numbers::pi / 180.0;
  const double cs = std::cos(phi), sn = std::sin(phi);
  // F.6.5.1: the midpoint difference in the ellipse's axes.
  const PointD h = 0.5 * (p0 - p1);
  const PointD q{cs * h.x + sn * h.y, -sn * h.x + cs * h.y};
  // F.6.6: radii too small are scaled up until the ellipse just reaches.
  const double lambda = (q.x * q.x) / (rx * rx) + (q.y * q.y) / (ry * ry);
  if (lambda > 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
  // F.6.5.2: the centre in the ellipse's axes.
  const double num = rx * rx * ry * ry - rx * rx * q.y * q.y - ry * ry * q.x * q.x;
  const double den = rx * rx * q.y * q.y + ry * ry * q.x * q.x;
  double k = den > 0 ? std::sqrt(std::max(0.0, num / den)) : 0.0;
  if (large == sweep) k = -k;
  const PointD cq{k * rx * q.y / ry, -k * ry * q.x / rx};
  // F.6.5.3: the centre in user space.
  const PointD mid = 0.5 * (p0 + p1);
  const PointD c{cs * cq.x - sn * cq.y + mid.x, sn * cq.x + cs * cq.y + mid.y};
  // F.6.5.5-6: start angle and sweep.
  const PointD u{(q.x - cq.x) / rx, (q.y - cq.y) / ry};
  const PointD v{(-q.x - cq.x) / rx, (-q.y - cq.y) / ry};
  const double theta = angle_between({1, 0}, u);
  double dtheta = angle_between(u, v);
  if (!sweep && dtheta > 0) dtheta -= 2 * std::numbers::pi;
  if (sweep && dtheta < 0) dtheta += 2 * std::numbers::pi;
  // Chord sagitta R (1 - cos(step / 2)) <= flat with R the larger radius.
  const double r = std::max(rx, ry);
  const double step = flat >= r ? std::numbers::pi / 2 : 2 * std::acos(1 - flat / r);
  const auto n = static_cast<std::size_t>(
      std::clamp(std::ceil(std::abs(dtheta) / step), 1.0, static_cast<double>(kMaxPieces)));
  std::vector<PointD> out;
  for (std::size_t i = 1; i < n; ++i) {
    const double t = theta + dtheta * static_cast<double>(i) / static_cast<double>(n);
    const double ex = rx * std::cos(t), ey = ry * std::sin(t);
    out.push_back({cs * ex - sn * ey + c.x, sn * ex + cs * ey + c.y});
  }
  out.push_back(p1); // the exact end point, not a rounded one
  return out;
}

std::vector<Subpath> parse_path_data(std::string_view d, double flatness) {
  if (!(flatness > 0)) throw PathDataError("flatness must be positive");
  return PathParser(d, flatness).run();
}

std::vector<PointD> parse_point_list(std::string_view text) {
  NumberScanner in(text);
  std::vector<double> v;
  for (in.skip_separators(); !in.done(); in.skip_separators()) {
    const auto x = in.number();
    if (!x) throw PathDataError("point list at offset " + in.where() + ": expected a number");
    v.push_back(*x);
  }
  if (v.size() % 2 != 0) throw PathDataError("point list has an odd count of numbers");
  std::vector<PointD> out;
  for (std::size_t i = 0; i + 1 < v.size(); i += 2) out.push_back({v[i], v[i + 1]});
  return out;
}

} // namespace penshape::snap
