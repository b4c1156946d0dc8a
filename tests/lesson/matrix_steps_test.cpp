// The radiosity-matrix lesson's three matrix steps show what their texts say: K (its diagonal is 1), K of a
// room with a brighter floor, and rho F (its spectral radius is the one the text prints). Their matrices, and
// so their figures, differ.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "lesson/step_runner.h"
#include "lesson_test_support.h"

using namespace rt::lesson;

TEST(MatrixSteps, EachShowsTheMatrixItsTextIsAbout) {
  test::ensureAnalyticMethod();
  const Lesson lesson = test::shippedLesson("radiosity-matrix");
  StepRunner runner(test::repoFolders().scenes);
  const Step& assembly = test::stepWithFigure(lesson, "assembly");
  const Step& dominance = test::stepWithFigure(lesson, "dominance");
  const Step& spectral = test::stepWithFigure(lesson, "spectral");
  EXPECT_EQ(assembly.parameters.matrix, "K");
  EXPECT_EQ(dominance.parameters.matrix, "K");
  EXPECT_EQ(spectral.parameters.matrix, "rhoF");
  const StepResult a = runner.run(lesson, assembly);
  const StepResult d = runner.run(lesson, dominance);
  const StepResult s = runner.run(lesson, spectral);
  ASSERT_TRUE(a.shownMatrix && d.shownMatrix && s.shownMatrix);
  // K = I - rho F: ones on the diagonal (no flat face sees itself), -rho_i F_ij elsewhere.
  const auto n = a.shownMatrix->rows();
  for (Eigen::Index i = 0; i < n; ++i) EXPECT_DOUBLE_EQ((*a.shownMatrix)(i, i), 1.0);
  EXPECT_DOUBLE_EQ(a.value("K.diagonal.min").value_or(0), 1.0);
  const Eigen::MatrixXd expectedK =
      Eigen::MatrixXd::Identity(n, n) - a.mesh.reflectance.col(1).asDiagonal() * Eigen::MatrixXd(*a.F);
  EXPECT_TRUE(a.shownMatrix->isApprox(expectedK, 1e-14));
  // rho F's spectral radius is the one the text prints.
  const Eigen::VectorXcd eigenvalues = Eigen::EigenSolver<Eigen::MatrixXd>(*s.shownMatrix).eigenvalues();
  EXPECT_NEAR(eigenvalues.cwiseAbs().maxCoeff(), s.value("spectral-radius").value_or(-1), 1e-6);
  // Three different matrices, so three different figures.
  EXPECT_FALSE(a.shownMatrix->isApprox(*d.shownMatrix));
  EXPECT_FALSE(a.shownMatrix->isApprox(*s.shownMatrix));
  EXPECT_FALSE(d.shownMatrix->isApprox(*s.shownMatrix));
}
