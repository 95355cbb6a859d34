#include "penshape/core/version.hpp"

#include <CGAL/config.h>
#include <CGAL/version.h>
#include <gmp.h>

namespace penshape {

std::string version() { return PENSHAPE_VERSION; }

std::vector<std::string> geometry_library_versions() {
  return {std::string("CGAL ") + CGAL_STRINGIZE(CGAL_VERSION), std::string("GMP ") + gmp_version};
}

} // namespace penshape
