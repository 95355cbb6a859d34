#pragma once
// The zip-packaged .xopp (Xournal++ 1.1+: `mimetype`, `META-INF/version`, `content.xml`, and
// attachments such as PDFs and images) in memory, with libzip: the XML read out, and the package
// written back with only content.xml replaced (every other entry copied as it was stored).
#include <cstddef>
#include <string>
#include <string_view>

namespace penshape::snap {

// Whether the bytes start with a zip local file header ("PK\3\4").
bool looks_zipped(std::string_view bytes);

// The entry's bytes. Throws SnapInputError when the bytes are no zip, the entry is missing or
// unreadable, or it expands beyond `limit` bytes (reading stops there).
std::string zip_entry(std::string_view zip, const char* name, std::size_t limit);

// The zip with the entry's content replaced; the other entries are kept as they were.
std::string zip_with_entry(std::string_view zip, const char* name, const std::string& content);

} // namespace penshape::snap
