// The stochastic radiosity lesson's claims, on its own steps: the local lines' counts agree with the
// quadrature's form factors within their binomial standard errors, the steps that say they compute no form
// factor compute none (the step result holds no F and the runner's cache computed nothing), the regular
// solver's burn-in is the bound the text gives, and the comparison's numbers say what its text says.
#include <gtest/gtest.h>

#include <cmath>

#include "core/solvers/local_lines_solver.h"
#include "lesson/step_runner.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

struct Ran {
  StepResult result;
  int formFactorComputations = 0;
};

Ran runStep(const std::string& figure) {
  const Lesson lesson = test::shippedLesson("stochastic");
  const Step& step = test::stepWithFigure(lesson, figure);
  StepRunner runner(test::repoFolders().scenes);
  Ran ran{runner.run(lesson, step), 0};
  ran.formFactorComputations = runner.formFactorComputations();
  EXPECT_NO_THROW(resolvedText(lesson, step, ran.result));
  return ran;
}

TEST(StochasticLesson, LocalLinesLandWhereTheFormFactorsSayWithinTheirNoise) {
  if (!test::hasMethod("quadrature")) GTEST_SKIP() << "quadrature is not in this build";
  const StepResult r = runStep("local-lines").result;
  const double lines = *r.value("lines");
  EXPECT_EQ(lines, 4000);
  // The text: within a few standard errors on every surface, and one of them the floor.
  EXPECT_LE(*r.value("lines-z.max"), 3.5);
  const double floor = *r.value("lines.floor"), exact = *r.value("lines.floor.reference");
  EXPECT_NEAR(floor, exact, 3.5 * *r.value("lines-se.floor"));
  EXPECT_NEAR(*r.value("lines-se.floor"), std::sqrt(floor * (1 - floor) / lines), 1e-12);
  // The open front lets lines escape, as the quadrature's row says.
  const double escaped = *r.value("lines.escaped"), escapedExact = *r.value("lines.escaped.reference");
  EXPECT_GT(escapedExact, 0.01);
  EXPECT_NEAR(escaped, escapedExact, 3.5 * std::sqrt(escapedExact * (1 - escapedExact) / lines));
  // The step's F is the Monte Carlo one: the row of the light is the counts.
  EXPECT_TRUE(r.F);
  EXPECT_EQ(r.method, "montecarlo");
}

TEST(StochasticLesson, TheSolversThatTraceLinesComputeNoFormFactor) {
  for (const char* figure : {"regular", "incremental"}) {
    const Ran ran = runStep(figure);
    EXPECT_FALSE(ran.result.F) << figure << ": the step result holds a form-factor matrix";
    EXPECT_EQ(ran.formFactorComputations, 0) << figure << ": the pipeline computed form factors";
    EXPECT_GT(*ran.result.value("rays"), 0) << figure;
    EXPECT_EQ(ran.result.B.rows(), static_cast<Eigen::Index>(ran.result.mesh.size())) << figure;
  }
}

TEST(StochasticLesson, RegularJacobiDiscardsItsBurnInAndAveragesTheRest) {
  const StepResult r = runStep("regular").result;
  const double tolerance = *r.value("tolerance");
  const int burnIn = static_cast<int>(*r.value("burn-in"));
  const double rhoMax = r.mesh.reflectance.maxCoeff();
  EXPECT_EQ(burnIn, regularBurnIn(rhoMax, tolerance));
  EXPECT_LE(std::pow(rhoMax, burnIn), tolerance);
  EXPECT_GT(std::pow(rhoMax, burnIn - 1), tolerance);
  EXPECT_GT(*r.value("iterations"), burnIn);
  EXPECT_EQ(*r.value("converged"), 1.0);
  EXPECT_LE(*r.value("standard-error"), tolerance);
  // N lines every iteration, the same number each time.
  EXPECT_EQ(*r.value("rays"), *r.value("iterations") * *r.value("rays-per-iteration"));
}

TEST(StochasticLesson, IncrementalJacobiShootsMostInItsFirstIteration) {
  const StepResult r = runStep("incremental").result;
  EXPECT_EQ(*r.value("converged"), 1.0);
  EXPECT_EQ(*r.value("rays.first"), *r.value("rays-per-iteration"));
  // Later iterations shoot less power and so cast fewer lines than the first.
  const double later = (*r.value("rays") - *r.value("rays.first")) / (*r.value("iterations") - 1);
  EXPECT_LT(later, *r.value("rays.first"));
  EXPECT_LT(*r.value("unshot.first"), 1.0);
}

}  // namespace
}  // namespace rt::lesson
