#pragma once
// The shared real data (../shared/data): its directory and whole-file reads for tests.
#include <string>

namespace penshape::test {

// $PENSHAPE_SHARED_DATA_DIR when set, else the compile-time default.
std::string shared_data_dir();
// The file's bytes; throws std::runtime_error when it cannot be read.
std::string read_file(const std::string& path);
std::string read_shared(const std::string& relative);

} // namespace penshape::test
