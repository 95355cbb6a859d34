// $1 gesture logs through pugixml (dollar_xml.hpp).
#include "dollar_xml.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <pugixml.hpp>
#include <sstream>

namespace penshape::dollar {
namespace {

class Source {
 public:
  Source(std::string_view text, const std::string& origin) : text_(text), origin_(origin) {}

  [[nodiscard]] std::size_t line_at(std::ptrdiff_t offset) const {
    const auto end = static_cast<std::size_t>(std::max<std::ptrdiff_t>(offset, 0));
    return 1 + static_cast<std::size_t>(
                   std::count(text_.begin(), text_.begin() + std::min(end, text_.size()), '\n'));
  }
  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw DollarXmlError(origin_ + ":" + std::to_string(line) + ": " + what);
  }

 private:
  std::string_view text_;
  const std::string& origin_;
};

std::optional<double> finite_number(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '+')) s.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

StrokePoint point_of(const pugi::xml_node& node, const Source& source) {
  const std::size_t line = source.line_at(node.offset_debug());
  StrokePoint p;
  for (const char* key : {"X", "Y", "T"}) {
    const pugi::xml_attribute a = node.attribute(key);
    if (!a) {
      if (key[0] == 'T') break;
      source.fail(line, std::string("<Point> without attribute ") + key);
    }
    const std::optional<double> v = finite_number(a.value());
    if (!v) {
      source.fail(
          line, std::string("attribute ") + key + "=\"" + a.value() + "\" is not a finite number");
    }
    (key[0] == 'X' ? p.x : key[0] == 'Y' ? p.y : p.t) = key[0] == 'T' ? *v / 1000.0 : *v;
  }
  return p;
}

} // namespace

std::string Gesture::kind() const {
  std::string k = name;
  while (!k.empty() && k.back() >= '0' && k.back() <= '9') k.pop_back();
  return k;
}

Gesture parse_dollar_xml(std::string_view text, const std::string& origin) {
  const Source source(text, origin);
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
  if (!parsed && parsed.status != pugi::status_no_document_element) { // empty: no <Gesture>
    source.fail(source.line_at(parsed.offset),
                std::string("unterminated or malformed XML: ") + parsed.description());
  }
  pugi::xml_node gesture;
  for (const pugi::xml_node& e : doc.children()) {
    if (e.type() != pugi::node_element) continue;
    if (std::string_view(e.name()) != "Gesture") {
      source.fail(source.line_at(e.offset_debug()),
                  std::string("<") + e.name() + "> where <Gesture> was expected");
    }
    if (gesture) source.fail(source.line_at(e.offset_debug()), "more than one <Gesture> element");
    gesture = e;
  }
  if (!gesture)
    source.fail(source.line_at(static_cast<std::ptrdiff_t>(text.size())), "no <Gesture> element");
  Gesture g;
  g.name = gesture.attribute("Name").value();
  g.subject = gesture.attribute("Subject").value();
  g.line = source.line_at(gesture.offset_debug());
  for (const pugi::xml_node& p : gesture.children("Point")) g.points.push_back(point_of(p, source));
  return g;
}

Gesture read_dollar_xml(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DollarXmlError(path.string() + ":0: cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_dollar_xml(text.str(), path.string());
}

} // namespace penshape::dollar
