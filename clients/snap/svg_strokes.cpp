// Walking an SVG tree for strokes (see svg_strokes.hpp).
#include "svg_strokes.hpp"

#include <cmath>
#include <cstring>
#include <set>

#include "outline_centerline.hpp"
#include "path_data.hpp"
#include "snap_error.hpp"
#include "svg_style.hpp"

namespace penshape::snap {
namespace {

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

class Walker {
 public:
  Walker(const std::string& text, const SvgScope& scope) : text_(text), scope_(scope) {
    ids_.insert(scope.ids.begin(), scope.ids.end());
  }

  std::vector<SvgPage> run(const pugi::xml_node& root) {
    pages_.push_back({"root", {}});
    const bool whole = scope_.ids.empty() && scope_.layer.empty();
    walk(root, Affine{}, computed_style(root, PaintStyle{}), 0, whole);
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
  void walk(const pugi::xml_node& parent, const Affine& ctm, const PaintStyle& style,
            std::size_t page, bool in_scope) {
    for (const pugi::xml_node& n : parent.children()) {
      if (n.type() != pugi::node_element || skipped_container(n.name())) continue;
      const std::string id = n.attribute("id").value();
      bool scoped = in_scope;
      if (!id.empty() && ids_.contains(id)) scoped = true, found_.insert(id);
      Affine m = ctm;
      if (const auto t = n.attribute("transform")) {
        try {
          m = ctm.then_inner(parse_transform(t.value()));
        } catch (const TransformError& e) {
          throw SnapInputError(describe(n, text_) + ": transform: " + e.what());
        }
      }
      const PaintStyle st = computed_style(n, style);
      const char* name = n.name();
      if (std::strcmp(name, "g") == 0 || std::strcmp(name, "a") == 0) {
        std::size_t p = page;
        if (is_layer(n)) {
          const char* label = n.attribute("inkscape:label").value();
          pages_.push_back({*label ? label : id, {}});
          p = pages_.size() - 1;
          if (!scope_.layer.empty() && id == scope_.layer) scoped = true, found_.insert(id);
        }
        walk(n, m, st, p, scoped);
      } else if (scoped) {
        stroke(n, m, st, page);
      }
    }
  }

  void stroke(const pugi::xml_node& n, const Affine& m, const PaintStyle& st, std::size_t page) {
    const std::string name = n.name();
    if (name != "path" && name != "polyline" && name != "line") return;
    const bool stroked = st.stroke != "none";
    const bool filled = st.fill != "none" && name != "line";
    const bool pencil = stroked && !filled;
    const bool calligraphy = name == "path" && filled && !stroked;
    if (!pencil && !calligraphy) return;
    if (!m.is_similarity()) return; // a skewed or squashed pen is no disk: left as drawn
    double width = 0;
    if (pencil) width = checked_width(n, st.stroke_width);
    const std::vector<Subpath> paths = geometry(n, width > 0 ? width / 8 : 0.05);
    if (paths.size() != 1) return; // several subpaths are several strokes' worth: left alone
    const Subpath& path = paths.front();
    if (path.points.size() < 2 || (calligraphy && !path.closed)) {
      throw SnapInputError(describe(n, text_) + ": a stroke with " +
                           std::to_string(path.points.size()) +
                           " point(s); a stroke needs at least 2");
    }
    SvgStroke s;
    s.element = n;
    s.to_root = m;
    s.calligraphy = calligraphy;
    s.ink.where = describe(n, text_);
    std::vector<PointD> pts;
    for (const PointD& p : path.points) pts.push_back(m.apply(p));
    double radius = width / 2 * m.scale();
    if (calligraphy) {
      const auto c = outline_centerline(pts);
      if (!c) return; // a blob, not a stroke's outline
      pts = c->points;
      radius = c->radius;
      if (!(radius * 2 <= kMaxStrokeWidth)) {
        throw SnapInputError(describe(n, text_) + ": outline of a pen wider than " +
                             std::to_string(static_cast<int>(kMaxStrokeWidth)));
      }
    }
    for (std::size_t i = 0; i < pts.size(); ++i) {
      s.ink.points.push_back({pts[i].x, pts[i].y, static_cast<double>(i)});
      s.ink.radii.push_back(radius);
    }
    pages_[page].strokes.push_back(std::move(s));
  }

  double checked_width(const pugi::xml_node& n, const std::string& text) {
    const auto w = parse_length(text);
    if (!w) throw SnapInputError(describe(n, text_) + ": stroke-width '" + text + "' is no length");
    if (!(*w > 0) || *w > kMaxStrokeWidth) {
      throw SnapInputError(describe(n, text_) + ": stroke-width " + text +
                           " is absurd (a pen is wider than 0 and at most " +
                           std::to_string(static_cast<int>(kMaxStrokeWidth)) + " units)");
    }
    return *w;
  }

  std::vector<Subpath> geometry(const pugi::xml_node& n, double flatness) {
    const std::string name = n.name();
    try {
      if (name == "path") return parse_path_data(n.attribute("d").value(), flatness);
      if (name == "polyline") return {{parse_point_list(n.attribute("points").value()), false}};
      const auto num = [&](const char* a) {
        const auto v = parse_length(n.attribute(a).as_string("0"));
        if (!v) throw PathDataError(std::string(a) + " is no number");
        return *v;
      };
      return {{{{num("x1"), num("y1")}, {num("x2"), num("y2")}}, false}};
    } catch (const PathDataError& e) {
      throw SnapInputError(describe(n, text_) + ": " + e.what());
    }
  }

  const std::string& text_;
  const SvgScope& scope_;
  std::set<std::string> ids_, found_;
  std::vector<SvgPage> pages_;
};

} // namespace

std::string describe(const pugi::xml_node& element, const std::string& text) {
  std::string out = element.name();
  if (const auto id = element.attribute("id")) out += std::string("#") + id.value();
  return out + " (line " + std::to_string(line_of(text, element.offset_debug())) + ")";
}

std::vector<SvgPage> read_svg_strokes(const pugi::xml_document& doc, const std::string& text,
                                      const SvgScope& scope) {
  return Walker(text, scope).run(doc.document_element());
}

} // namespace penshape::snap
