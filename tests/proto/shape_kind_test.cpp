// ShapeClass <-> v1::ShapeKind: one table read both ways, so every class the recognizer names
// reaches a client and comes back as itself; what a client cannot name maps to nothing.
#include <gtest/gtest.h>

#include <set>

#include "penshape/proto/shape_kind.hpp"

namespace penshape {
namespace {

TEST(ProtoShapeKind, EveryClassRoundTripsThroughItsOwnKind) {
  std::set<int> kinds;
  for (int c = static_cast<int>(ShapeClass::kFreeform); c <= static_cast<int>(ShapeClass::kPolygon);
       ++c) {
    const auto shape = static_cast<ShapeClass>(c);
    const v1::ShapeKind kind = proto::to_proto(shape);
    SCOPED_TRACE(to_string(shape));
    EXPECT_NE(kind, v1::SHAPE_KIND_UNSPECIFIED);
    EXPECT_TRUE(kinds.insert(kind).second) << "two classes share a kind";
    EXPECT_EQ(proto::from_proto(kind), shape);
  }
}

TEST(ProtoShapeKind, FreeformIsKindNone) {
  EXPECT_EQ(proto::to_proto(ShapeClass::kFreeform), v1::SHAPE_KIND_NONE);
  EXPECT_EQ(proto::from_proto(v1::SHAPE_KIND_NONE), ShapeClass::kFreeform);
}

TEST(ProtoShapeKind, UnspecifiedAndUnknownKindsNameNoClass) {
  EXPECT_EQ(proto::from_proto(v1::SHAPE_KIND_UNSPECIFIED), std::nullopt);
  EXPECT_EQ(proto::from_proto(static_cast<v1::ShapeKind>(9999)), std::nullopt);
}

} // namespace
} // namespace penshape
