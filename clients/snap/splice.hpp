#pragma once
// Changing only what was replaced: an element's byte range in the text it was parsed from, and
// the text with such ranges replaced, so that everything outside them (whitespace, entities,
// attribute quoting, comments) comes out byte for byte.
#include <cstddef>
#include <string>
#include <vector>

#include <pugixml.hpp>

namespace penshape::snap {

struct Edit {
  std::size_t begin = 0, end = 0; // the bytes [begin, end) of the original text
  std::string text;               // what comes in their place
};

// The element's bytes in `text` (the buffer pugixml parsed, whose offset_debug it reports): from
// its '<' to the end of its end tag (or of its empty-element tag). Throws std::runtime_error when
// the text there is no such element (a bug, not bad input).
Edit element_range(const std::string& text, const pugi::xml_node& element);

// The element as XML text, without indentation.
std::string node_text(const pugi::xml_node& element);

// `text` with the edits (disjoint ranges, any order) applied.
std::string spliced(const std::string& text, std::vector<Edit> edits);

} // namespace penshape::snap
