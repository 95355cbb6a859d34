#pragma once
// Exact (rational) lower bounds on the Hausdorff distance between Clipper's union of integer
// polygons, as the ink polygon runs it (core/src/ink/ink_union.hpp), and the exact union of the
// same polygons: shared by the ink union tests.
#include <clipper.hpp>

namespace penshape::test {

// A lower bound on H(Clipper's union of `pieces`, their exact union S), in grid units, computed
// exactly: the distance to S of every vertex of Clipper's output O outside S, and to O of every
// exact crossing of input edges and every input vertex outside O; with `scanlines`, also of the
// points of every input and output edge on every vertex's horizontal line (where Clipper's sweep
// decides), each outside the other region.
double union_error_lower_bound(const ClipperLib::Paths& pieces, bool scanlines = false);

} // namespace penshape::test
