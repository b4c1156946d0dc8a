// radiosity solve --method NAME: every solver by name on the furnace cube (B = E / (1 - rho) = 2), seeds,
// --verbose, the automatic choice, the iteration cap, and shooting with rows computed at the shooter.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace rt::test {
namespace {

// B_r, B_g, B_b of every element of a radiosity CSV written by `solve --output`.
std::vector<double> readRadiosities(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    for (int column = 0; std::getline(ss, cell, ','); ++column)
      if (column >= 4 && column < 7) values.push_back(std::stod(cell));
  }
  return values;
}

std::string furnace(const std::string& arguments) {
  return cliPath() + " solve " + sourcePath("scenes/furnace-cube.json") + " " + arguments;
}

class SolveMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(SolveMethod, FurnaceCubeByName) {
  const std::string name = GetParam();
  const bool stochastic = name == "stochastic-jacobi" || name == "random-walk" || name == "local-lines";
  const std::string out = scratchDir("solve-method-" + name) + "/B.csv";
  std::string log;
  // analytic: exact in a convex enclosure, so B shows the solver to 1e-8.
  ASSERT_EQ(
      runCommand(furnace("--no-subdivide --solver " + name + " --method analytic --seed 7 --tolerance " +
                         (stochastic ? "1e-3" : "1e-10") + " --output " + out),
                 &log),
      0)
      << log;
  EXPECT_NE(log.find("solve (" + name + "): success"), std::string::npos) << log;
  const auto B = readRadiosities(out);
  ASSERT_EQ(B.size(), 18u);
  // Stochastic: about 1000 rays per iteration by default, a few percent of noise per element.
  double mean = 0;
  for (double b : B) {
    EXPECT_NEAR(b, 2.0, stochastic ? 0.15 : 1e-8) << name;
    mean += b / static_cast<double>(B.size());
  }
  EXPECT_NEAR(mean, 2.0, stochastic ? 0.05 : 1e-8) << name;
  if (stochastic) {
    // The same seed gives the same numbers; another seed other noise.
    const std::string again = scratchDir("solve-method-" + name + "-again") + "/B.csv";
    const std::string other = scratchDir("solve-method-" + name + "-other") + "/B.csv";
    ASSERT_EQ(runCommand(furnace("--no-subdivide --solver " + name +
                                 " --method analytic --seed 7 --tolerance 1e-3 --output " + again)),
              0);
    ASSERT_EQ(runCommand(furnace("--no-subdivide --solver " + name +
                                 " --method analytic --seed 8 --tolerance 1e-3 --output " + other)),
              0);
    EXPECT_EQ(readRadiosities(again), B);
    EXPECT_NE(readRadiosities(other), B);
  }
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, SolveMethod,
                         ::testing::Values("direct", "jacobi", "gauss-seidel", "southwell", "progressive",
                                           "bounces", "stochastic-jacobi", "random-walk", "local-lines"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(SolveMethods, VerbosePrintsOneLinePerIteration) {
  std::string log;
  ASSERT_EQ(runCommand(furnace("--no-subdivide --method gauss-seidel --verbose"), &log), 0) << log;
  std::smatch summary;
  ASSERT_TRUE(std::regex_search(log, summary, std::regex("success after (\\d+) iterations"))) << log;
  const int iterations = std::stoi(summary[1]);
  EXPECT_GT(iterations, 3);
  int lines = 0;
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line))
    if (std::regex_search(line, std::regex("^iteration \\d+: residual [0-9.e+-]+, unshot power"))) ++lines;
  EXPECT_EQ(lines, iterations) << log;
  EXPECT_NE(log.find("iteration 1: residual"), std::string::npos) << log;
  // Shooting methods name the shooter of each iteration.
  ASSERT_EQ(runCommand(furnace("--no-subdivide --method southwell --verbose --max-iterations 4"), &log), 0)
      << log;
  EXPECT_NE(log.find("iteration 4: residual"), std::string::npos) << log;
  EXPECT_NE(log.find(", shooter "), std::string::npos) << log;
}

TEST(SolveMethods, DirectIsChosenForASmallSceneWhenNoMethodIsNamed) {
  std::string log;
  ASSERT_EQ(runCommand(furnace("--subdivide 2"), &log), 0) << log;
  EXPECT_NE(log.find("solve (direct): success after 1 iteration,"), std::string::npos) << log;
}

// The form factors' tolerance has its own option: --tolerance is the solver's. Unset, the quadrature method
// runs at its own default, not at the exact method's 1e-9.
TEST(SolveMethods, FormFactorToleranceReachesTheQuadratureMethod) {
  std::string log;
  ASSERT_EQ(
      runCommand(furnace("--subdivide 2 --method quadrature --ff-tolerance 1e-3 --tolerance 1e-9"), &log), 0)
      << log;
  EXPECT_NE(log.find("absolute tolerance 0.001"), std::string::npos) << log;
  ASSERT_EQ(runCommand(furnace("--subdivide 2 --method quadrature"), &log), 0) << log;
  EXPECT_NE(log.find("absolute tolerance 1e-05"), std::string::npos) << log;
  EXPECT_NE(runCommand(furnace("--subdivide 2 --method quadrature --ff-tolerance 2"), &log), 0);
  EXPECT_NE(log.find("--ff-tolerance"), std::string::npos) << log;
}

TEST(SolveMethods, UnknownNameListsTheKnownOnesBeforeAnyWork) {
  std::string log;
  EXPECT_NE(runCommand(furnace("--solver conjugate-gradient"), &log), 0);
  EXPECT_NE(log.find("unknown solver 'conjugate-gradient'"), std::string::npos) << log;
  EXPECT_NE(log.find("gauss-seidel"), std::string::npos) << log;
  EXPECT_EQ(log.find("form factors ("), std::string::npos) << log;
}

TEST(SolveMethods, IterationCapIsANonConvergenceWarningWithTheResidual) {
  const std::string out = scratchDir("solve-cap") + "/B.csv";
  std::string log;
  ASSERT_EQ(
      runCommand(
          furnace("--no-subdivide --solver jacobi --method analytic --max-iterations 3 --output " + out),
          &log),
      0)
      << log;
  EXPECT_NE(log.find("solve (jacobi): no convergence after 3 iterations"), std::string::npos) << log;
  std::smatch warning;
  ASSERT_TRUE(
      std::regex_search(log, warning,
                        std::regex("not converged: the iteration cap \\(--iterations 3\\) was reached "
                                   "with relative residual ([0-9.e+-]+)")))
      << log;
  // Jacobi from B = E: after 3 sweeps the residual is the next bounce, rho^4 = 1/16.
  EXPECT_NEAR(std::stod(warning[1]), 0.0625, 1e-9) << log;
  for (double b : readRadiosities(out)) EXPECT_NEAR(b, 1.0 + 0.5 + 0.25 + 0.125, 1e-12);
  EXPECT_EQ(log.find("nan"), std::string::npos) << log;
}

TEST(SolveMethods, ShootingWithRowsAtTheShooterStoresNoMatrix) {
  for (const std::string formFactors : {"hemicube", "raycast"}) {
    const std::string out = scratchDir("solve-no-matrix-" + formFactors) + "/B.csv";
    std::string log;
    ASSERT_EQ(runCommand(furnace("--subdivide 2 --method southwell --no-matrix --formfactors " + formFactors +
                                 " --resolution 64 --tolerance 1e-8 --output " + out),
                         &log),
              0)
        << log;
    EXPECT_NE(log.find("form factors (" + formFactors + "): one row per shot, no matrix stored"),
              std::string::npos)
        << log;
    EXPECT_NE(log.find("solve (southwell, rows on demand): success"), std::string::npos) << log;
    EXPECT_TRUE(std::regex_search(log, std::regex("\\d+ rows computed"))) << log;
    const auto B = readRadiosities(out);
    ASSERT_EQ(B.size(), 72u);
    for (double b : B) EXPECT_NEAR(b, 2.0, 0.1) << formFactors;  // the method's error, not the solver's
  }
}

TEST(SolveMethods, NoMatrixNeedsAShootingMethodAndARowMethod) {
  std::string log;
  EXPECT_NE(runCommand(furnace("--method jacobi --no-matrix"), &log), 0);
  EXPECT_NE(log.find("--no-matrix needs a shooting solver"), std::string::npos) << log;
  EXPECT_NE(runCommand(furnace("--method southwell --no-matrix --formfactors analytic"), &log), 0);
  EXPECT_NE(log.find("--method hemicube or --method raycast"), std::string::npos) << log;
  // Without --method, --no-matrix shoots (southwell) with hemicube rows.
  ASSERT_EQ(runCommand(furnace("--no-subdivide --no-matrix --resolution 32"), &log), 0) << log;
  EXPECT_NE(log.find("form factors (hemicube): one row per shot"), std::string::npos) << log;
  EXPECT_NE(log.find("solve (southwell, rows on demand)"), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::test
