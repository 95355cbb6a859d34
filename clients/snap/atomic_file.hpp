#pragma once
// Writing a file so that readers see the old file or the whole new one, never a part: the bytes
// go to a temporary file in the same folder, are flushed to disk, and the temporary is renamed
// over the target.
#include <string>
#include <string_view>

namespace penshape::snap {

// Throws std::runtime_error naming the file; the temporary is removed on failure. A new file
// gets mode 0666 minus the umask; an existing one keeps its mode.
void write_file_atomically(const std::string& path, std::string_view bytes);

} // namespace penshape::snap
