#pragma once
// gzip in memory with zlib (Xournal++ files are gzip-compressed XML).
#include <string>
#include <string_view>

namespace penshape::snap {

// Whether the bytes start with the gzip magic number.
bool looks_gzipped(std::string_view bytes);

// The decompressed bytes; throws SnapInputError on a corrupt or truncated stream, or output
// beyond `limit` bytes (a compression bomb).
std::string gunzip(std::string_view bytes, std::size_t limit = std::size_t{1} << 30);

std::string gzip(std::string_view bytes);

} // namespace penshape::snap
