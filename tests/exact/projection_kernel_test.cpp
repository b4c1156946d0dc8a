// The geometric core of visibility from a point (horizon clipping, clipping to the pyramid, central
// projection), run with both kernels: exact constructions and floating constructions (CGAL's Epeck and
// Epick). Each case has a closed form; the exact kernel must reproduce it to the last bit of the double
// conversion, the floating one to rounding.
#include <gtest/gtest.h>

#include "core/polygon.h"
#include "exact/exact_kernel.h"

namespace rt::exact {
namespace {

using detail::Arithmetic;

const Polygon kCeiling{{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};  // facing -z
const Vec3 kDown(0, 0, -1), kUp(0, 0, 1);

class ProjectionKernel : public ::testing::TestWithParam<Arithmetic> {
 protected:
  double tolerance() const { return GetParam() == Arithmetic::Exact ? 1e-15 : 1e-13; }
  detail::ProjectionResult project(const Vec3& x, const std::vector<Polygon>& occluders,
                                   const Polygon& receiver = kCeiling) const {
    return detail::projectOccluders(x, kUp, receiver, kDown, occluders, GetParam());
  }
};

TEST_P(ProjectionKernel, ParallelSquareScalesAboutThePoint) {
  const Polygon square{{0.4, 0.4, 0.25}, {0.6, 0.4, 0.25}, {0.6, 0.6, 0.25}, {0.4, 0.6, 0.25}};
  const auto r = project(Vec3(0.5, 0.5, 0), {square});
  ASSERT_TRUE(r.receiverFacesPoint);
  ASSERT_EQ(r.projections.size(), 1u);
  // Height 1/4 of the way: the shadow is the square scaled by 4 about (0.5, 0.5): [0.1, 0.9]^2, in the plane
  // z = 1.
  EXPECT_NEAR(polygonArea(r.projections[0]), 0.64, tolerance());
  for (const Vec3& v : r.projections[0]) {
    EXPECT_NEAR(v.z(), 1.0, tolerance());
    EXPECT_NEAR(std::abs(v.x() - 0.5), 0.4, tolerance());
  }
  // CCW seen from the receiver's front (from below): the Newell normal points along the receiver normal.
  EXPECT_GT(newellNormal(r.projections[0]).dot(kDown), 0);
}

TEST_P(ProjectionKernel, ShadowIsClippedToThePyramid) {
  const Polygon large{{-5, -5, 0.5}, {5, -5, 0.5}, {5, 5, 0.5}, {-5, 5, 0.5}};
  const auto r = project(Vec3(0.2, 0.7, 0), {large});
  ASSERT_EQ(r.projections.size(), 1u);
  EXPECT_NEAR(polygonArea(r.projections[0]), 1.0, tolerance());  // exactly the receiver
}

TEST_P(ProjectionKernel, OccluderStraddlingTheReceiverPlaneLosesTheFarPart) {
  // Vertical square x = 0.5, z from 0.5 to 1.5: only z <= 1 can block.
  const Polygon wall{{0.5, -2, 0.5}, {0.5, 3, 0.5}, {0.5, 3, 1.5}, {0.5, -2, 1.5}};
  const auto r = project(Vec3(0.25, 0.5, 0), {wall});
  ASSERT_EQ(r.projections.size(), 1u);
  // From x = 0.25: the edge z = 0.5 projects to x = 0.75, the edge z = 1 stays at x = 0.5: shadow [0.5, 0.75]
  // x [0, 1].
  EXPECT_NEAR(polygonArea(r.projections[0]), 0.25, tolerance());
}

TEST_P(ProjectionKernel, OccludersBehindThePointOrThroughItCastNothing) {
  const Polygon below{{0, 0, -0.5}, {1, 0, -0.5}, {1, 1, -0.5}, {0, 1, -0.5}};
  const Polygon edgeOn{{0.5, -1, 0}, {0.5, 2, 0}, {0.5, 2, 0.5}, {0.5, -1, 0.5}};  // vertical plane through x
  const Polygon beyond{{0, 0, 1.5}, {1, 0, 1.5}, {1, 1, 1.5}, {0, 1, 1.5}};
  const auto r = project(Vec3(0.5, 0.5, 0), {below, edgeOn, beyond});
  EXPECT_TRUE(r.receiverFacesPoint);
  EXPECT_TRUE(r.projections.empty());
}

TEST_P(ProjectionKernel, HorizonClipsAStraddlingReceiver) {
  // Receiver plane x + z = 1 (tilted, facing the source side), half of it below the source plane z = 0.
  const Polygon tilted{{0.5, 0, 0.5}, {0.5, 1, 0.5}, {1.5, 1, -0.5}, {1.5, 0, -0.5}};
  const Vec3 n = newellNormal(tilted).normalized();
  const auto r = detail::projectOccluders(Vec3(0.2, 0.5, 0), kUp, tilted, n, {}, GetParam());
  ASSERT_TRUE(r.receiverFacesPoint);
  for (const Vec3& v : r.clippedReceiver) EXPECT_GE(v.z(), -tolerance());
  EXPECT_NEAR(polygonArea(r.clippedReceiver), 0.5 * polygonArea(tilted), tolerance());
}

TEST_P(ProjectionKernel, PointBehindTheReceiverSeesNothing) {
  const auto r = project(Vec3(0.5, 0.5, 2), {});
  EXPECT_FALSE(r.receiverFacesPoint);
}

INSTANTIATE_TEST_SUITE_P(BothKernels, ProjectionKernel,
                         ::testing::Values(Arithmetic::Exact, Arithmetic::Floating), [](const auto& info) {
                           return info.param == Arithmetic::Exact ? "Exact" : "Floating";
                         });

TEST(ProjectionKernelAgreement, ExactAndFloatingAgreeOnAGeneralOccluder) {
  const Polygon tilted{{0.1, 0.2, 0.3}, {0.9, 0.1, 0.45}, {0.7, 0.8, 0.6}, {0.2, 0.7, 0.5}};
  const Vec3 x(0.33, 0.41, 0);
  const auto e = detail::projectOccluders(x, kUp, kCeiling, kDown, {tilted}, Arithmetic::Exact);
  const auto f = detail::projectOccluders(x, kUp, kCeiling, kDown, {tilted}, Arithmetic::Floating);
  ASSERT_EQ(e.projections.size(), 1u);
  ASSERT_EQ(f.projections.size(), 1u);
  ASSERT_EQ(e.projections[0].size(), f.projections[0].size());
  for (std::size_t k = 0; k < e.projections[0].size(); ++k)
    EXPECT_LT((e.projections[0][k] - f.projections[0][k]).norm(), 1e-14);
}

}  // namespace
}  // namespace rt::exact
