#pragma once
// Parses an SVG document as XML (Boost.PropertyTree's parser: it throws on malformed XML) and
// finds elements by id, for tests of the pictures.
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace penshape::testing {

using boost::property_tree::ptree;

inline ptree parse_xml(const std::string& text) {
  std::istringstream in(text);
  ptree tree;
  boost::property_tree::read_xml(in, tree);
  return tree;
}

inline std::optional<std::string> attribute(const ptree& node, const std::string& name) {
  const auto v = node.get_optional<std::string>("<xmlattr>." + name);
  if (!v) return std::nullopt;
  return *v;
}

// The first element (depth first) whose id attribute is `id`.
inline const ptree* find_by_id(const ptree& node, const std::string& id) {
  for (const auto& [name, child] : node) {
    if (name == "<xmlattr>") continue;
    if (attribute(child, "id") == id) return &child;
    if (const ptree* found = find_by_id(child, id)) return found;
  }
  return nullptr;
}

// Every element named `tag` below `node`.
inline void collect(const ptree& node, const std::string& tag, std::vector<const ptree*>& out) {
  for (const auto& [name, child] : node) {
    if (name == "<xmlattr>") continue;
    if (name == tag) out.push_back(&child);
    collect(child, tag, out);
  }
}

inline std::vector<const ptree*> elements(const ptree& node, const std::string& tag) {
  std::vector<const ptree*> out;
  collect(node, tag, out);
  return out;
}

// The numbers of an SVG path's d attribute, per command letter: {{'M', {x, y}}, {'L', ...}}.
struct PathCommand {
  char op;
  std::vector<double> args;
};
inline std::vector<PathCommand> parse_path(const std::string& d) {
  std::vector<PathCommand> out;
  std::size_t i = 0;
  while (i < d.size()) {
    const char c = d[i];
    if (std::isalpha(static_cast<unsigned char>(c)) != 0) {
      out.push_back({c, {}});
      ++i;
    } else if (c == ' ' || c == ',') {
      ++i;
    } else {
      std::size_t used = 0;
      const double v = std::stod(d.substr(i), &used);
      if (!out.empty()) out.back().args.push_back(v);
      i += used;
    }
  }
  return out;
}

} // namespace penshape::testing
