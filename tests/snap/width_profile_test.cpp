// The certificate widened to the widths drawn and written (clients/snap/width_profile.hpp):
// the written radii's spread around the certified pen is added; for a path certificate the drawn
// radii's spread too; one pen throughout changes nothing; past the tolerance, no certificate.
#include <gtest/gtest.h>

#include "snap/width_profile.hpp"

namespace penshape::snap {
namespace {

Recognition circle(const char* method) {
  Recognition r;
  r.shape = ShapeClass::kCircle;
  r.certificate = {true, 2.0, 10.0, 1.0, 0.1, method};
  return r;
}

TEST(WidthProfile, OnePenChangesNothing) {
  Recognition r = circle("ink");
  EXPECT_TRUE(certify_width_profile(r, {1.0, 1.0}, {1.0}));
  EXPECT_EQ(r.certificate.bound, 2.0);
  EXPECT_EQ(r.certificate.method, "ink");
}

TEST(WidthProfile, InkCertificateAddsTheWrittenSpread) {
  Recognition r = circle("ink");
  // The drawn radii are in the ink certificate already.
  EXPECT_TRUE(certify_width_profile(r, {0.5, 1.0, 2.5}, {0.1, 9.0}));
  EXPECT_GE(r.certificate.bound, 3.5);
  EXPECT_LT(r.certificate.bound, 3.5 + 1e-12);
  EXPECT_EQ(r.certificate.method, "ink+width_profile");
}

TEST(WidthProfile, PathCertificateAddsBothSpreads) {
  Recognition r = circle("path");
  EXPECT_TRUE(certify_width_profile(r, {1.5}, {0.25, 1.0}));
  EXPECT_GE(r.certificate.bound, 3.25);
  EXPECT_LT(r.certificate.bound, 3.25 + 1e-12);
}

TEST(WidthProfile, PastTheToleranceNoCertificate) {
  Recognition r = circle("ink");
  EXPECT_FALSE(certify_width_profile(r, {1.0, 9.5}, {1.0}));
  EXPECT_FALSE(r.certificate.certified);
  EXPECT_GT(r.certificate.bound, r.certificate.epsilon);
}

} // namespace
} // namespace penshape::snap
