// Walking an SVG tree for strokes (see svg_strokes.hpp).
#include "svg_strokes.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <set>

#include "outline_centerline.hpp"
#include "path_data.hpp"
#include "snap_error.hpp"
#include "svg_style.hpp"

namespace penshape::snap {
namespace {

// A calligraphy outline whose half-width varies more than this (upper over lower quartile, away
// from the caps) is a variable-width stroke: left as drawn, since a constant pen would lose its
// form.
constexpr double kMaxCalligraphyWidthRatio = 1.4;

// Content that is never drawn as it stands, or is not ink.
bool skipped_container(const char* name) {
  static const std::set<std::string> kSkip{
      "defs",   "clipPath", "mask",          "pattern",
      "symbol", "marker",   "metadata",      "sodipodi:namedview",
      "title",  "desc",     "text",          "flowRoot",
      "image",  "use",      "foreignObject", "style",
      "script", "switch"};
  return kSkip.contains(name);
}

bool is_layer(const pugi::xml_node& n) {
  return std::strcmp(n.name(), "g") == 0 &&
         std::strcmp(n.attribute("inkscape:groupmode").value(), "layer") == 0;
}

// Why an element that looks like a stroke is left as drawn (empty: silently).
struct NotAStroke {
  std::string why;
};

double segment_distance(PointD p, PointD a, PointD b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t =
      len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// How the outline's half-width varies along the centre line: the upper quartile of the distances
// from the centre line's middle 60% to the outline over the lower one (corners, where the centre
// estimate cuts inside, do not count).
double width_ratio(const std::vector<PointD>& centre, const std::vector<PointD>& ring) {
  std::vector<double> d;
  const std::size_t n = centre.size();
  for (std::size_t i = n / 5; i < n - n / 5; ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < ring.size(); ++k) {
      best = std::min(best, segment_distance(centre[i], ring[k], ring[(k + 1) % ring.size()]));
    }
    d.push_back(best);
  }
  if (d.empty()) return 1.0;
  std::sort(d.begin(), d.end());
  const double lo = d[d.size() / 4], hi = d[d.size() - 1 - d.size() / 4];
  return lo > 0 ? hi / lo : std::numeric_limits<double>::infinity();
}

// What only strokes that may be grouped share: the tool, paint, markers, dashes and parent.
std::string style_key(const pugi::xml_node& n, const PaintStyle& st, bool calligraphy) {
  std::string key = calligraphy ? "calligraphy" : "pencil";
  key += "|" + st.stroke + "|" + st.fill + "|" + st.fill_opacity + "|" +
         n.attribute("class").value() + "|" + std::to_string(n.parent().offset_debug());
  for (const auto& [k, v] : parse_style(n.attribute("style").value())) {
    if (k != "stroke-width") key.append("|").append(k).append(":").append(v);
  }
  for (const char* a : {"marker-start", "marker-mid", "marker-end", "stroke-dasharray",
                        "stroke-opacity", "opacity", "stroke-linecap", "filter"}) {
    key.append("|").append(n.attribute(a).value());
  }
  return key;
}

// Whether the transform's entries are finite and within kMaxCoordinate (extreme transforms are
// reported, like extreme coordinates).
bool within_range(const Affine& m) {
  for (const double v : {m.a, m.b, m.c, m.d, m.e, m.f}) {
    if (!(std::abs(v) <= kMaxCoordinate)) return false;
  }
  return true;
}

// One element to visit, with what it inherits.
struct Frame {
  pugi::xml_node node;
  Affine ctm;
  PaintStyle style;
  std::size_t page = 0;
  bool scoped = false;
};

class Walker {
 public:
  Walker(const std::string& text, const SvgScope& scope, std::vector<std::string>& warnings)
      : lines_(text), scope_(scope), warnings_(warnings) {
    ids_.insert(scope.ids.begin(), scope.ids.end());
  }

  std::vector<SvgPage> run(const pugi::xml_node& root) {
    pages_.push_back({"root", {}});
    const bool whole = scope_.ids.empty() && scope_.layer.empty();
    std::vector<Frame> stack;
    push_children({root, Affine{}, computed_style(root, PaintStyle{}), 0, whole}, stack);
    while (!stack.empty()) {
      const Frame f = std::move(stack.back());
      stack.pop_back();
      visit(f, stack);
    }
    for (const std::string& id : ids_) {
      if (!found_.contains(id)) throw SnapInputError("no element with id '" + id + "'");
    }
    if (!scope_.layer.empty() && !found_.contains(scope_.layer)) {
      throw SnapInputError("no layer with id '" + scope_.layer + "'");
    }
    std::vector<SvgPage> out;
    for (auto& p : pages_) {
      if (!p.strokes.empty()) out.push_back(std::move(p));
    }
    return out;
  }

 private:
  // The children go on the stack last first, so they are visited in document order.
  static void push_children(const Frame& f, std::vector<Frame>& stack) {
    const std::size_t mark = stack.size();
    for (const pugi::xml_node& n : f.node.children()) {
      if (n.type() == pugi::node_element && !skipped_container(n.name())) {
        stack.push_back({n, f.ctm, f.style, f.page, f.scoped});
      }
    }
    std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(mark), stack.end());
  }

  void visit(Frame f, std::vector<Frame>& stack) {
    const pugi::xml_node n = f.node;
    const std::string id = n.attribute("id").value();
    if (!id.empty() && ids_.contains(id)) f.scoped = true, found_.insert(id);
    if (const auto t = n.attribute("transform")) {
      try {
        f.ctm = f.ctm.then_inner(parse_transform(t.value()));
      } catch (const TransformError& e) {
        warnings_.push_back(describe(n, lines_) + ": transform: " + e.what() + ": left as drawn");
        return;
      }
    }
    f.style = computed_style(n, f.style);
    if (std::strcmp(n.name(), "g") == 0 || std::strcmp(n.name(), "a") == 0) {
      if (is_layer(n)) {
        const char* label = n.attribute("inkscape:label").value();
        pages_.push_back({*label ? label : id, {}});
        f.page = pages_.size() - 1;
        if (!scope_.layer.empty() && id == scope_.layer) f.scoped = true, found_.insert(id);
      }
      push_children(f, stack);
    } else if (f.scoped) {
      try {
        stroke(n, f.ctm, f.style, f.page);
      } catch (const NotAStroke& e) {
        if (!e.why.empty())
          warnings_.push_back(describe(n, lines_) + ": " + e.why + ": left as drawn");
      }
    }
  }

  void stroke(const pugi::xml_node& n, const Affine& m, const PaintStyle& st, std::size_t page) {
    const std::string name = n.name();
    if (name != "path" && name != "polyline" && name != "polygon" && name != "line") return;
    const bool stroked = st.stroke != "none";
    const bool filled = st.fill != "none" && name != "line";
    const bool pencil = stroked && !filled;
    const bool calligraphy = name == "path" && filled && !stroked;
    if (!pencil && !calligraphy) return;
    if (!within_range(m)) {
      throw NotAStroke{"transform beyond +-1e6 (scale or offset) or not finite"};
    }
    if (!m.is_similarity()) return; // a skewed or squashed pen is no disk: left as drawn
    const double width = pencil ? checked_width(st.stroke_width) : 0.0;
    const std::vector<Subpath> paths = geometry(n, width > 0 ? width / 8 : 0.05);
    if (paths.size() != 1) return; // several subpaths are several strokes' worth: left alone
    const Subpath& path = paths.front();
    if (path.points.size() < 2) throw NotAStroke{""}; // a dot, drawn as it is
    const std::optional<PenLine> line = pen_line(path, m, width, calligraphy);
    if (!line) return;
    const double radius = line->radius;
    if (!(radius > 0) || !(radius * 2 <= kMaxStrokeWidth)) {
      throw NotAStroke{"a pen " + std::to_string(2 * radius) + " units wide (transform included)"};
    }
    SvgStroke s;
    s.element = n;
    s.to_root = m;
    s.calligraphy = calligraphy;
    s.ink.where = describe(n, lines_);
    s.ink.locator = locator(n);
    s.ink.style = style_key(n, st, calligraphy);
    for (std::size_t i = 0; i < line->points.size(); ++i) {
      s.ink.points.push_back({line->points[i].x, line->points[i].y, static_cast<double>(i)});
      s.ink.radii.push_back(radius);
    }
    if (!coordinates_in_range(s.ink.points)) {
      throw NotAStroke{"coordinates beyond +-1e6 units (transform included) or not finite"};
    }
    pages_[page].strokes.push_back(std::move(s));
  }

  // The pen's centre line in root units and its radius: a pencil path as drawn (a closed one
  // back to its start: the closing side is ink too), a calligraphy fill's centre line; nothing
  // when a fill is a blob or of varying width (left as drawn).
  struct PenLine {
    std::vector<PointD> points;
    double radius = 0;
  };
  static std::optional<PenLine> pen_line(const Subpath& path, const Affine& m, double width,
                                         bool calligraphy) {
    PenLine out;
    for (const PointD& p : path.points) out.points.push_back(m.apply(p));
    if (!calligraphy) {
      if (path.closed) out.points.push_back(out.points.front());
      out.radius = width / 2 * m.scale();
      return out;
    }
    const auto c = outline_centerline(out.points);       // a fill closes the outline, Z or not
    if (!c || c->points.size() < 2) return std::nullopt; // a blob, not a stroke's outline
    if (width_ratio(c->points, out.points) > kMaxCalligraphyWidthRatio) return std::nullopt;
    return PenLine{c->points, c->radius};
  }

  static double checked_width(const std::string& text) {
    const auto w = parse_length(text);
    if (!w) throw NotAStroke{"stroke-width '" + text + "' is no length"};
    if (!(*w > 0) || *w > kMaxStrokeWidth) {
      throw NotAStroke{"stroke-width " + text + " is beyond what snap redraws (wider than 0 " +
                       "and at most " + std::to_string(static_cast<int>(kMaxStrokeWidth)) +
                       " units)"};
    }
    return *w;
  }

  static std::vector<Subpath> geometry(const pugi::xml_node& n, double flatness) {
    const std::string name = n.name();
    try {
      if (name == "path") return parse_path_data(n.attribute("d").value(), flatness);
      if (name == "polyline" || name == "polygon") {
        return {{parse_point_list(n.attribute("points").value()), name == "polygon"}};
      }
      const auto num = [&](const char* a) {
        const auto v = parse_length(n.attribute(a).as_string("0"));
        if (!v) throw PathDataError(std::string(a) + " is no number");
        return *v;
      };
      return {{{{num("x1"), num("y1")}, {num("x2"), num("y2")}}, false}};
    } catch (const PathDataError& e) {
      throw NotAStroke{e.what()};
    }
  }

  const LineIndex lines_;
  const SvgScope& scope_;
  std::vector<std::string>& warnings_;
  std::set<std::string> ids_, found_;
  std::vector<SvgPage> pages_;
};

} // namespace

std::string describe(const pugi::xml_node& element, const LineIndex& lines) {
  std::string out = element.name();
  if (const auto id = element.attribute("id")) out += std::string("#") + id.value();
  return out + " (line " + std::to_string(lines.line(element.offset_debug())) + ")";
}

std::string locator(const pugi::xml_node& element) {
  if (const char* id = element.attribute("id").value(); *id != '\0') return id;
  std::vector<std::string> steps;
  for (pugi::xml_node n = element; n.type() == pugi::node_element; n = n.parent()) {
    std::size_t k = 1;
    for (pugi::xml_node s = n.previous_sibling(n.name()); s; s = s.previous_sibling(n.name())) ++k;
    steps.push_back(std::string(n.name()) + "[" + std::to_string(k) + "]");
  }
  std::string out;
  for (auto it = steps.rbegin(); it != steps.rend(); ++it) out += "/" + *it;
  return out;
}

std::vector<SvgPage> read_svg_strokes(const pugi::xml_document& doc, const std::string& text,
                                      const SvgScope& scope, std::vector<std::string>& warnings) {
  return Walker(text, scope, warnings).run(doc.document_element());
}

} // namespace penshape::snap
