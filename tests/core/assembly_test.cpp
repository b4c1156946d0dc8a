#include "core/assembly.h"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "support/test_systems.h"

namespace rt {
namespace {

TEST(Assembly, DenseAndSparseAgree) {
  const test::OwnedSystem s = test::randomSystem(25, 11, 0.9, 0.05);
  const Eigen::VectorXd rho = s.system.reflectance.col(1);
  const Eigen::MatrixXd dense = assembleDense(*s.F, rho);
  const Eigen::MatrixXd fromSparse = Eigen::MatrixXd(assembleSparse(*s.F, rho));
  EXPECT_EQ(dense, fromSparse);
  for (int i = 0; i < 25; ++i)
    for (int j = 0; j < 25; ++j) EXPECT_EQ(dense(i, j), (i == j ? 1.0 : 0.0) - rho(i) * (*s.F)(i, j));
}

TEST(Assembly, StorageFollowsFill) {
  const test::OwnedSystem sparse = test::randomSystem(40, 5, 0.9, 0.02);
  const AssembledMatrix a = assemble(sparse.system, 0);
  EXPECT_LT(a.fill, kSparseFillThreshold);
  EXPECT_TRUE(a.sparse);
  EXPECT_EQ(a.dense.size(), 0);
  const test::OwnedSystem cube = test::colouredCube();
  const AssembledMatrix b = assemble(cube.system, 2);
  EXPECT_FALSE(b.sparse);
  EXPECT_NEAR(b.fill, 30.0 / 36.0, 1e-15);
  EXPECT_EQ(b.toDense(), assembleDense(*cube.F, cube.system.reflectance.col(2)));
  EXPECT_EQ(a.toDense(), assembleDense(*sparse.F, sparse.system.reflectance.col(0)));
}

TEST(Assembly, SpectralRadiusOfClosedUniformSceneIsRho) {
  // Rows of F sum to 1, so F has eigenvalue 1 with eigenvector ones, and rho F has spectral radius rho.
  for (double rho : {0.3, 0.9, 0.999}) {
    const test::OwnedSystem s = test::furnaceCube(rho);
    const SpectralRadiusEstimate e = spectralRadius(*s.F, s.system.reflectance.col(0));
    EXPECT_TRUE(e.converged);
    EXPECT_NEAR(e.value, rho, 1e-10);
    EXPECT_LE(e.lower, rho + 1e-12);
    EXPECT_GE(e.upper, rho - 1e-12);
  }
}

TEST(Assembly, SpectralRadiusWhenPlainPowerIterationOscillates) {
  // F = [0 1; 1 0] has eigenvalues +1 and -1.
  const test::OwnedSystem s = test::facingPlates(0.7);
  const SpectralRadiusEstimate e = spectralRadius(*s.F, s.system.reflectance.col(0));
  EXPECT_TRUE(e.converged);
  EXPECT_NEAR(e.value, 0.7, 1e-10);
}

TEST(Assembly, SpectralRadiusMatchesEigenvaluesOfRandomSystem) {
  const test::OwnedSystem s = test::randomSystem(30, 2);
  const Eigen::VectorXd rho = s.system.reflectance.col(0);
  const Eigen::MatrixXd M = rho.asDiagonal() * Eigen::MatrixXd(*s.F);
  const double expected = Eigen::EigenSolver<Eigen::MatrixXd>(M).eigenvalues().cwiseAbs().maxCoeff();
  const SpectralRadiusEstimate e = spectralRadius(*s.F, rho);
  EXPECT_NEAR(e.value, expected, 1e-8);
  EXPECT_LT(e.value, 0.95 * 0.8 + 1e-12);  // bounded by max rho * max row sum
}

TEST(Assembly, ConditionNumberOfTheCube) {
  // F of the cube is symmetric with eigenvalues 1, -o (x3), o - 2d (x2); K = I - rho F then has singular
  // values 1 - rho, 1 + rho o, 1 + rho (2d - o), so cond(K) = (1 + rho (2d - o)) / (1 - rho).
  for (double rho : {0.5, 0.99}) {
    const test::OwnedSystem s = test::furnaceCube(rho);
    const auto cond = conditionNumber(assembleDense(*s.F, s.system.reflectance.col(0)));
    ASSERT_TRUE(cond.has_value());
    const double expected = (1 + rho * (2 * test::kCubeAdjacent - test::kCubeOpposite)) / (1 - rho);
    EXPECT_NEAR(*cond, expected, 1e-10 * expected);
  }
}

TEST(Assembly, ConditionNumberLimits) {
  EXPECT_FALSE(
      conditionNumber(Eigen::MatrixXd::Identity(kMaxConditionSize + 1, kMaxConditionSize + 1)).has_value());
  EXPECT_TRUE(std::isinf(*conditionNumber(Eigen::MatrixXd::Zero(3, 3))));
  EXPECT_DOUBLE_EQ(*conditionNumber(Eigen::MatrixXd::Identity(4, 4)), 1.0);
}

TEST(Assembly, NilpotentRhoFHasSpectralRadiusZeroAndKHasNoNegativeZeros) {
  // A black emitter lighting a grey receiver: rho F = [0 0; a 0], (rho F)^2 = 0.
  FormFactorMatrix F(2, 2);
  F << 0, 0.2, 0.2, 0;
  const Eigen::Vector2d rho(0.0, 0.5);
  const SpectralRadiusEstimate radius = spectralRadius(F, rho);
  EXPECT_TRUE(radius.converged);
  EXPECT_EQ(radius.value, 0.0);
  EXPECT_EQ(radius.iterations, 2);
  const Eigen::MatrixXd K = assembleDense(F, rho);
  EXPECT_FALSE(std::signbit(K(0, 1)));  // 1 - 0 * 0.2 is +0, printed "0", not "-0"
  EXPECT_DOUBLE_EQ(K(1, 0), -0.1);
}

}  // namespace
}  // namespace rt
