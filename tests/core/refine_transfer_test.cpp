#include "core/refine/transfer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/formfactor/analytic.h"
#include "core/refine/dense_transfer.h"
#include "refine_test_scenes.h"

namespace rt {
namespace {

// Differential area under the corner of a parallel a x b rectangle at distance c (Howell's catalogue, B-3).
double cornerRectangle(double a, double b, double c) {
  const double A = a / c, B = b / c;
  return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
          B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
         (2 * std::numbers::pi);
}

TEST(RefineTransfer, PointToParallelSquareMatchesClosedForm) {
  // Square [-1,1]^2 at height 2 facing down, point at the origin facing up: four corner rectangles 1 x 1.
  const Polygon P{{-1, -1, 2}, {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}};
  const double F = pointToPolygonFormFactor(Vec3::Zero(), Vec3(0, 0, 1), P);
  EXPECT_NEAR(F, 4 * cornerRectangle(1, 1, 2), 1e-14);
  // Seen from behind (one-sided) nothing arrives.
  EXPECT_EQ(pointToPolygonFormFactor(Vec3(0, 0, 3), Vec3(0, 0, -1), P), 0.0);
}

TEST(RefineTransfer, HorizonClippingKeepsOnlyTheVisibleHalf) {
  // A wall square straddling the point's tangent plane: only the part above the plane counts, which is the
  // same as the upper half alone.
  const Polygon wall{{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
  const Polygon upper{{-1, 1, 0}, {1, 1, 0}, {1, 1, 1}, {-1, 1, 1}};
  const double full = pointToPolygonFormFactor(Vec3::Zero(), Vec3(0, 0, 1), wall);
  const double half = pointToPolygonFormFactor(Vec3::Zero(), Vec3(0, 0, 1), upper);
  EXPECT_GT(full, 0.0);
  EXPECT_NEAR(full, half, 1e-14);
}

TEST(RefineTransfer, VisibilityOracleSeesTheOccluder) {
  const Scene s = test::shadowScene();
  const VisibilityOracle v(s);
  EXPECT_FALSE(v.segmentClear(Vec3(0, 0, 0), Vec3(0, 0, 2), 2, 0));     // straight up through the occluder
  EXPECT_TRUE(v.segmentClear(Vec3(1.8, 0, 0), Vec3(0.2, 0, 2), 2, 0));  // around it
  const auto samples = stratifiedSamples(s.patches[0].vertices, 4);
  EXPECT_NEAR(v.visibleFraction(Vec3(0, 0, 0), samples, 2, 0), 0.0, 1e-12);    // umbra
  EXPECT_NEAR(v.visibleFraction(Vec3(1.5, 0, 0), samples, 2, 0), 1.0, 1e-12);  // outside the penumbra
  const double penumbra = v.visibleFraction(Vec3(1.0, 0, 0), samples, 2, 0);
  EXPECT_GT(penumbra, 0.2);
  EXPECT_LT(penumbra, 0.8);
}

TEST(RefineTransfer, ClosedRoomRowsSumToOneAndReciprocityIsExact) {
  const Scene s = test::closedRoom();
  MeshOptions o;
  o.mode = MeshOptions::Mode::Count;
  o.count = 3;
  const Mesh mesh = buildMesh(s, o);
  std::vector<Polygon> storage;
  const auto pieces = piecesOfMesh(mesh, storage);
  const VisibilityOracle v(s);
  std::size_t pairs = 0;
  const FormFactorMatrix F = updateFormFactors({}, {}, pieces, v, {}, noProgress(), "F", pairs);
  EXPECT_EQ(pairs, mesh.size() * (mesh.size() - 1) / 2);
  const Eigen::VectorXd A = mesh.areas();
  for (Eigen::Index i = 0; i < F.rows(); ++i) {
    EXPECT_NEAR(F.row(i).sum(), 1.0, 0.03) << "row " << i;
    for (Eigen::Index j = 0; j < F.cols(); ++j) EXPECT_NEAR(A[i] * F(i, j), A[j] * F(j, i), 1e-12);
  }
}

}  // namespace
}  // namespace rt
