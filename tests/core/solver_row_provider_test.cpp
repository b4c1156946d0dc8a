// Shooting with rows computed at the shooter (hemicube or ray casting), no n x n matrix stored: the same
// answer as shooting with the stored matrix of the same method, and the direct solution within the method's
// error.
#include "core/solvers/row_providers.h"

#include <gtest/gtest.h>

#include "core/formfactor/formfactor_method.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/shooting_solvers.h"
#include "formfactor_scenes.h"

namespace rt {
namespace {

struct RoomWithBlock {
  Scene scene = test::roomWithBlock();
  Mesh mesh;
  RoomWithBlock() {
    scene.materials[0].reflectance = Rgb(0.7, 0.5, 0.3);  // strong interreflection: many shots
    mesh = test::meshOf(scene, 2);
  }
  FormFactorMatrix matrix(const std::string& method, const FormFactorOptions& options) const {
    FormFactorStats stats;
    return makeFormFactorMethod(method)->compute(mesh, options, noProgress(), stats);
  }
  RadiositySystem matrixFree() const {
    RadiositySystem s;
    s.reflectance = mesh.reflectance;
    s.emission = mesh.emission;
    s.areas = mesh.areas();
    return s;
  }
};

SolverOptions tight() {
  SolverOptions o;
  o.tolerance = 1e-12;
  o.maxIterations = 100000;
  o.recordHistory = false;
  return o;
}

RgbField direct(const Mesh& mesh, const FormFactorMatrix& F) {
  RgbField B;
  EXPECT_EQ(directSolve(RadiositySystem::fromMesh(mesh, F), B, {}), SolverStatus::Success);
  return B;
}

double relative(const RgbField& a, const RgbField& b) {
  return (a - b).norm() / b.norm();
}

// A vector's entries as the row a provider writes.
std::span<double> span(Eigen::VectorXd& row) {
  return {row.data(), static_cast<std::size_t>(row.size())};
}

// Shooting row i spreads P_i F_ij to j; shooting with a stored matrix G spreads P_i G_ji A_j / A_i. They are
// the same shot when G = A^-1 F^T A, the matrix whose columns are the provider's rows.
FormFactorMatrix columnsFromRows(const FormFactorMatrix& F, const Eigen::VectorXd& areas) {
  return areas.cwiseInverse().asDiagonal() * F.transpose() * areas.asDiagonal();
}

TEST(RowProvider, HemicubeRowsAreTheHemicubeMatrixRows) {
  const RoomWithBlock room;
  FormFactorOptions options;
  options.hemicubeResolution = 48;
  const FormFactorMatrix F = room.matrix("hemicube", options);
  const FormFactorRowProvider rows = makeRowProvider("hemicube", room.mesh, options);
  Eigen::VectorXd row(F.cols());
  for (int i = 0; i < static_cast<int>(room.mesh.size()); i += 5) {
    rows(i, span(row));
    EXPECT_EQ(row.transpose(), F.row(i)) << "row " << i;
  }
}

TEST(RowProvider, HemicubeRowsMakeTheMatrixWithTheCountsAndNotesOfCompute) {
  const RoomWithBlock room;
  FormFactorOptions options;
  options.hemicubeResolution = 48;
  const auto method = makeFormFactorMethod("hemicube");
  FormFactorStats computed, gathered;
  const FormFactorMatrix F = method->compute(room.mesh, options, noProgress(), computed);
  const FormFactorRowProvider rows = makeRowProvider("hemicube", room.mesh, options);
  FormFactorMatrix apart = FormFactorMatrix::Zero(F.rows(), F.cols());
  for (int i = 0; i < static_cast<int>(room.mesh.size()); ++i)
    rows(i, {apart.row(i).data(), room.mesh.size()});
  const FormFactorMatrix made = method->fromRows(std::move(apart), room.mesh, options, gathered);
  EXPECT_EQ(made, F);
  EXPECT_EQ(gathered.pairsComputed, static_cast<std::size_t>((F.array() > 0).count()));
  EXPECT_GT(gathered.pairsComputed, 0u);
  EXPECT_EQ(gathered.pairsComputed, computed.pairsComputed);
  EXPECT_EQ(gathered.notes, computed.notes);
  EXPECT_EQ(gathered.warnings, computed.warnings);
}

TEST(RowProvider, RaycastRowsAreTheRaycastMatrixRows) {
  const RoomWithBlock room;
  FormFactorOptions options;
  options.samples = 64;
  const FormFactorMatrix F = room.matrix("raycast", options);
  const FormFactorRowProvider rows = makeRowProvider("raycast", room.mesh, options);
  Eigen::VectorXd row(F.cols());
  double worst = 0;
  for (int i = 0; i < static_cast<int>(room.mesh.size()); ++i) {
    rows(i, span(row));
    ASSERT_TRUE(row.allFinite());
    worst = std::max(worst, (row.transpose() - F.row(i)).cwiseAbs().maxCoeff());
  }
  // Each pair is sampled on its smaller element in both, the other direction by reciprocity: the same
  // numbers.
  EXPECT_LT(worst, 1e-12);
}

class ShootingWithRows : public ::testing::TestWithParam<std::string> {};

TEST_P(ShootingWithRows, AgreesWithStoredMatrixShootingAndWithDirect) {
  const std::string method = GetParam();
  const RoomWithBlock room;
  FormFactorOptions options;
  options.hemicubeResolution = 64;
  options.samples = 64;
  const FormFactorMatrix F = room.matrix(method, options);
  const Eigen::VectorXd areas = room.mesh.areas();

  int rowsAsked = 0;
  const FormFactorRowProvider provider = makeRowProvider(method, room.mesh, options);
  ShootingSolver solver(false);
  solver.setOptions(tight());
  solver.setRowProvider([&](int i, std::span<double> row) {
    ++rowsAsked;
    provider(i, row);
  });
  const RadiositySystem matrixFree = room.matrixFree();
  const RgbField withRows = solver.compute(matrixFree).solve();
  ASSERT_EQ(solver.info(), SolverStatus::Success) << toString(solver.info());
  ASSERT_TRUE(withRows.allFinite());
  EXPECT_EQ(rowsAsked, solver.iterations());

  // The provider's rows as one stored matrix (for the comparison only).
  FormFactorMatrix rowsMatrix(F.rows(), F.cols());
  for (int i = 0; i < F.rows(); ++i) provider(i, {rowsMatrix.row(i).data(), room.mesh.size()});
  const FormFactorMatrix G = columnsFromRows(rowsMatrix, areas);
  RgbField withMatrix;
  ASSERT_EQ(southwell(RadiositySystem::fromMesh(room.mesh, G), withMatrix, tight()), SolverStatus::Success);
  EXPECT_LT(relative(withRows, withMatrix), 1e-10);

  // Against the method's own matrix and the exact (analytic, ray-cast visibility) answer: the method's error.
  const RgbField methodDirect = direct(room.mesh, F);
  const RgbField reference = direct(room.mesh, room.matrix("analytic-visibility", {}));
  // Raycast rows are the rows of a reciprocal matrix, so shooting them solves the matrix's own system;
  // hemicube rows are not reciprocal and shooting them differs by the hemicube's reciprocity error (measured
  // 3 %).
  EXPECT_LT(relative(withRows, methodDirect), method == "raycast" ? 1e-9 : 0.05);
  // Both within the method's own error of the reference (measured: hemicube 3.7 %, raycast 0.8 %).
  EXPECT_LT(relative(withRows, reference), method == "raycast" ? 0.02 : 0.06);
}

INSTANTIATE_TEST_SUITE_P(Methods, ShootingWithRows, ::testing::ValuesIn(rowProviderMethods()));

TEST(RowProvider, OtherMethodsAreRefusedByName) {
  const RoomWithBlock room;
  try {
    makeRowProvider("analytic", room.mesh, {});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("analytic"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("hemicube"), std::string::npos);
  }
}

}  // namespace
}  // namespace rt
