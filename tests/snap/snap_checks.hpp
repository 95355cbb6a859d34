#pragma once
// Independent checks for snap's outputs: distances between points, polylines and the shapes the
// output files hold, computed here from the files (never from the snap library).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "penshape/core/polygon_set.hpp"

namespace penshape::test {

inline double segment_distance(PointD p, PointD a, PointD b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t =
      len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0;
  return std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
}

// Largest distance from the points to the polyline (closed: the last point joins the first).
inline double max_distance_to_polyline(const std::vector<PointD>& pts,
                                       const std::vector<PointD>& line, bool closed) {
  double worst = 0;
  for (const PointD& p : pts) {
    double best = 1e300;
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
      best = std::min(best, segment_distance(p, line[i], line[i + 1]));
    if (closed) best = std::min(best, segment_distance(p, line.back(), line.front()));
    worst = std::max(worst, best);
  }
  return worst;
}

inline std::vector<double> numbers_of(const std::string& text) {
  std::string s = text;
  std::replace(s.begin(), s.end(), ',', ' ');
  std::istringstream in(s);
  std::vector<double> out;
  for (double v = 0; in >> v;) out.push_back(v);
  return out;
}

inline std::vector<PointD> pairs_of(const std::string& text) {
  const auto v = numbers_of(text);
  std::vector<PointD> out;
  for (std::size_t i = 0; i + 1 < v.size(); i += 2) out.push_back({v[i], v[i + 1]});
  return out;
}

// "method=ink bound=1.2 epsilon=10 pen_radius=2" -> the value of `key`.
inline double certificate_value(const std::string& text, const std::string& key) {
  const auto at = text.find(key + "=");
  return at == std::string::npos ? NAN : std::stod(text.substr(at + key.size() + 1));
}

inline std::string xml_of(const pugi::xml_node& n) {
  std::ostringstream out;
  n.print(out, "", pugi::format_raw);
  return out.str();
}

inline pugi::xml_node by_id(const pugi::xml_document& doc, const std::string& id) {
  return doc.find_node([&](const pugi::xml_node& n) { return id == n.attribute("id").value(); });
}

} // namespace penshape::test
