#pragma once
// Version of penshape and of the exact-geometry libraries the core was built with.
#include <string>
#include <vector>

namespace penshape {

// penshape's own version, "MAJOR.MINOR.PATCH".
std::string version();

// e.g. {"CGAL 5.5.1", "GMP 6.2.1"}.
std::vector<std::string> geometry_library_versions();

} // namespace penshape
