// Element ranges by scanning the original text (see splice.hpp): tags are counted from the
// element's start tag until its own end tag, skipping comments, CDATA, processing instructions
// and quoted attribute values, so nested elements of the same name end where they should.
#include "splice.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace penshape::snap {
namespace {

// The index just past the tag that starts at text[i] == '<' (quotes respected).
std::size_t tag_end(std::string_view text, std::size_t i) {
  char quote = 0;
  for (++i; i < text.size(); ++i) {
    const char c = text[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      return i + 1;
    }
  }
  throw std::runtime_error("splice: unterminated tag");
}

// The index just past `close`, searched from i.
std::size_t past(std::string_view text, std::size_t i, std::string_view close) {
  const std::size_t at = text.find(close, i);
  if (at == std::string_view::npos) throw std::runtime_error("splice: unterminated markup");
  return at + close.size();
}

// Past the markup at text[i] == '<', and how it changes the element depth.
std::size_t skip_markup(std::string_view text, std::size_t i, int& depth) {
  const std::string_view rest = text.substr(i);
  if (rest.starts_with("<!--")) return past(text, i, "-->");
  if (rest.starts_with("<![CDATA[")) return past(text, i, "]]>");
  if (rest.starts_with("<?")) return past(text, i, "?>");
  const std::size_t end = tag_end(text, i);
  if (rest.starts_with("</")) {
    --depth;
  } else if (text[end - 2] != '/') {
    ++depth;
  }
  return end;
}

} // namespace

Edit element_range(const std::string& text, const pugi::xml_node& element) {
  const std::ptrdiff_t name = element.offset_debug();
  if (name < 1 || static_cast<std::size_t>(name) > text.size() ||
      text[static_cast<std::size_t>(name) - 1] != '<') {
    throw std::runtime_error("splice: no element at the parsed offset");
  }
  const std::size_t begin = static_cast<std::size_t>(name) - 1;
  int depth = 0;
  std::size_t i = skip_markup(text, begin, depth);
  while (depth > 0) {
    i = text.find('<', i);
    if (i == std::string::npos) throw std::runtime_error("splice: element without its end tag");
    i = skip_markup(text, i, depth);
  }
  return {begin, i, {}};
}

std::string node_text(const pugi::xml_node& element) {
  std::ostringstream out;
  element.print(out, "", pugi::format_raw, pugi::encoding_utf8);
  return out.str();
}

std::string spliced(const std::string& text, std::vector<Edit> edits) {
  std::sort(edits.begin(), edits.end(),
            [](const Edit& a, const Edit& b) { return a.begin < b.begin; });
  std::string out;
  out.reserve(text.size());
  std::size_t at = 0;
  for (const Edit& e : edits) {
    out.append(text, at, e.begin - at).append(e.text);
    at = e.end;
  }
  return out.append(text, at, std::string::npos);
}

} // namespace penshape::snap
