// The stochastic radiosity lesson's claims, on its own steps: the local lines' counts agree with the
// quadrature's form factors within their binomial standard errors, the steps that say they compute no form
// factor compute none (the step result holds no F and the runner's cache computed nothing), the regular
// solver's burn-in is the bound the text gives, the comparison's numbers say what its text says, the
// continuous walks agree with the discrete ones and the direct solution within their noise, and the figure of
// error against rays has the slopes and gains its text gives, on the open box and, where the control variate
// pays, on the closed one with regular Jacobi.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/progress.h"
#include "core/solvers/local_lines_solver.h"
#include "lesson/step_runner.h"
#include "lesson/step_settings.h"
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

TEST(StochasticLesson, TheComparisonSaysWhatItsTextSays) {
  if (!test::hasMethod("quadrature")) GTEST_SKIP() << "quadrature is not in this build";
  const Ran ran = runStep("stochastic-jacobi");
  const StepResult& r = ran.result;
  // F once, for the direct solve only.
  EXPECT_EQ(ran.formFactorComputations, 1);
  const double n = static_cast<double>(r.mesh.size());
  EXPECT_EQ(*r.value("bytes.F"), 8 * n * n);
  // "The estimated and the measured errors agree."
  for (const std::string s : {"local-lines-regular", "local-lines"}) {
    const double estimated = *r.value("standard-error." + s), measured = *r.value("rms-error." + s);
    EXPECT_GT(measured, 0.5 * estimated) << s;
    EXPECT_LT(measured, 1.5 * estimated) << s;
  }
  // "Its largest error sits on a small element."
  // Among the reflecting elements, as the error map shows them (the light's own B is mostly its emission).
  Eigen::VectorXd error = (r.B - r.reference).cwiseAbs().rowwise().mean();
  for (Eigen::Index i = 0; i < error.size(); ++i)
    if (r.mesh.emission.row(i).maxCoeff() > 0) error(i) = 0;
  Eigen::Index worst = 0;
  error.maxCoeff(&worst);
  Eigen::VectorXd areas = r.mesh.areas();
  const double area = areas(worst);
  std::sort(areas.begin(), areas.end());
  EXPECT_LT(area, areas(areas.size() / 2)) << "smaller than the median element";
  // Standard error times sqrt(rays): the regular solver is the less efficient over all its rays, about as
  // efficient over the iterates it averaged.
  const double perIteration = *r.value("rays-per-iteration");
  const double regular = std::pow(*r.value("standard-error.local-lines-regular"), 2);
  const double incremental =
      std::pow(*r.value("standard-error.local-lines"), 2) * *r.value("rays.local-lines");
  const double allRays = *r.value("rays.local-lines-regular");
  const double averaged = allRays - *r.value("burn-in.local-lines-regular") * perIteration;
  EXPECT_GT(regular * allRays, 2 * incremental);
  EXPECT_GT(regular * averaged, incremental / 1.5);
  EXPECT_LT(regular * averaged, incremental * 1.5);
  // The noise chart: the incremental solver's estimate grows as it adds light, the regular one's falls once
  // it averages.
  for (const SolverRun& run : r.runs) {
    if (run.label == "local-lines") {
      EXPECT_GT(run.standardErrors.back(), run.standardErrors.front());
    }
    if (run.label == "local-lines-regular") {
      const auto burnIn = static_cast<std::size_t>(*r.value("burn-in.local-lines-regular"));
      ASSERT_GT(run.standardErrors.size(), burnIn);
      EXPECT_LT(run.standardErrors.back(), 0.5 * run.standardErrors[burnIn - 1]);
    }
  }
  // "For a rough answer, yes, even here": the lines finish before F and the exact solve (measured about five
  // times sooner).
  EXPECT_LT(*r.value("seconds.local-lines"), *r.value("seconds.formfactors") + *r.value("seconds.direct"));
}

TEST(StochasticLesson, TheAbsorptionEstimatorNeedsMoreWalksForTheSameNoise) {
  if (!test::hasMethod("quadrature")) GTEST_SKIP() << "quadrature is not in this build";
  const StepResult r = runStep("random-walk").result;
  for (const std::string s : {"random-walk", "random-walk-absorption"}) {
    EXPECT_EQ(*r.value("converged." + s), 1.0) << s;
    EXPECT_LE(*r.value("standard-error." + s), *r.value("tolerance")) << s;
  }
  EXPECT_GT(*r.value("rays.random-walk-absorption"), 1.5 * *r.value("rays.random-walk"));
}

TEST(StochasticLesson, ContinuousWalksAgreeWithTheDiscreteOnesWithinTheirNoise) {
  if (!test::hasMethod("quadrature")) GTEST_SKIP() << "quadrature is not in this build";
  const Ran ran = runStep("photon-walks");
  const StepResult& r = ran.result;
  // F once, for the direct solve and the discrete walks; the photons trace rays.
  EXPECT_EQ(ran.formFactorComputations, 1);
  for (const std::string s : {"random-walk", "photon-density"}) {
    EXPECT_EQ(*r.value("converged." + s), 1.0) << s;
    EXPECT_LE(*r.value("standard-error." + s), *r.value("tolerance")) << s;
    // "each about its own standard error"
    EXPECT_LT(*r.value("rms-error." + s), 2.0 * *r.value("standard-error." + s)) << s;
    EXPECT_GT(*r.value("rms-error." + s), 0.3 * *r.value("standard-error." + s)) << s;
  }
  // The floor agrees with the direct solution within the noise of the walks.
  const double floor = *r.value("B.floor.direct");
  EXPECT_NEAR(*r.value("B.floor.photon-density"), floor, 3.0 * *r.value("tolerance") * floor);
  EXPECT_NEAR(*r.value("B.floor.random-walk"), floor, 3.0 * *r.value("tolerance") * floor);
}

// The walks the figure draws are the first walks of the step's own solvers: with the step's options, a solver
// whose first batch is those walks reports the power they carried, and their counts are the text's.
TEST(StochasticLesson, TheDrawnWalksAreTheFirstWalksOfTheStepsSolvers) {
  if (!test::hasMethod("quadrature")) GTEST_SKIP() << "quadrature is not in this build";
  const Lesson lesson = test::shippedLesson("stochastic");
  const Step& step = test::stepWithFigure(lesson, "photon-walks");
  const StepResult r = runStep("photon-walks").result;
  ASSERT_EQ(r.walks.size(), 2u);
  EXPECT_EQ(r.walks[0].solver, "random-walk");
  EXPECT_EQ(r.walks[1].solver, "photon-density");
  ASSERT_TRUE(r.F);
  const RadiositySystem withF = RadiositySystem::fromMesh(r.mesh, *r.F);
  const RadiositySystem traced = RadiositySystem::fromGeometry(r.mesh);
  for (const DrawnWalks& drawn : r.walks) {
    const std::string& s = drawn.solver;
    const auto count = static_cast<long>(drawn.walks.size());
    ASSERT_EQ(count, static_cast<long>(*r.value("drawn-walks"))) << s;
    double landings = 0, absorbed = 0, escaped = 0, absorbedPower = 0, escapedPower = 0;
    for (const RecordedWalk& walk : drawn.walks) {
      landings += static_cast<double>(walk.landings.size());
      absorbed += walk.end == RecordedWalk::End::Absorbed ? 1 : 0;
      escaped += walk.end == RecordedWalk::End::Escaped ? 1 : 0;
      absorbedPower += walk.absorbedPower;
      escapedPower += walk.escapedPower;
    }
    EXPECT_EQ(landings, *r.value("drawn-landings." + s)) << s;
    EXPECT_EQ(absorbed, *r.value("drawn-absorbed." + s)) << s;
    EXPECT_EQ(escaped, *r.value("drawn-escaped." + s)) << s;
    EXPECT_EQ(absorbed + escaped, count) << s << ": every walk ends";
    EXPECT_GT(landings, count) << s << ": some walks land more than once";
    // The solver itself, with the step's options, in batches of the drawn walks: its first batch.
    SolverOptions options = solverOptionsFor(step.parameters);
    options.raysPerIteration = count;
    options.maxIterations = 1;
    const SolveOutcome outcome =
        solveRadiosity(s == "photon-density" ? traced : withF, s, options, true, noProgress());
    ASSERT_FALSE(outcome.history.empty()) << s;
    const IterationRecord& first = outcome.history.front();
    EXPECT_NEAR(first.absorbedPower, absorbedPower / count, 1e-9 * first.emittedPower) << s;
    EXPECT_NEAR(first.escapedPower, escapedPower / count, 1e-9 * first.emittedPower) << s;
  }
}

TEST(StochasticLesson, SobolLinesAndTheControlVariateBeatPlainLinesAtEqualRays) {
  if (!test::hasMethod("quadrature")) GTEST_SKIP() << "quadrature is not in this build";
  const Ran ran = runStep("sampling");
  const StepResult& r = ran.result;
  EXPECT_EQ(ran.formFactorComputations, 1);  // the reference's F; the runs trace lines
  EXPECT_EQ(*r.value("seeds"), 4);
  EXPECT_EQ(*r.value("rowsum-rays"), 256.0 * static_cast<double>(r.mesh.size()));
  // "the -1/2 of the binomial error"; Sobol lines steeper.
  const double plain = *r.value("slope.monte-carlo"), sobol = *r.value("slope.quasi-monte-carlo");
  EXPECT_NEAR(plain, -0.5, 0.1);
  EXPECT_LT(sobol, plain - 0.04);
  EXPECT_NEAR(*r.value("slope.control-variate"), -0.5, 0.1);
  // At the largest budget: less error for both, the control variate's gain modest.
  EXPECT_GT(*r.value("gain.quasi-monte-carlo"), 1.5);
  EXPECT_GT(*r.value("gain.control-variate"), 1.0);
  EXPECT_LT(*r.value("gain.control-variate"), 1.5);  // "modest"
  // With its row sums' rays counted, still below plain Monte Carlo at the same rays.
  EXPECT_LT(*r.value("error-ratio.control-variate"), 1.0);
  EXPECT_LT(*r.value("gain.control-variate"), *r.value("gain.quasi-monte-carlo"));
  EXPECT_EQ(*r.value("rays-per-iteration"), 320000);
  for (const std::string v : {"monte-carlo", "control-variate", "quasi-monte-carlo"})
    EXPECT_GT(*r.value("rays." + v), *r.value("rays-per-iteration")) << v;
}

TEST(StochasticLesson, TheControlVariateWinsOnTheClosedBoxWithRegularJacobi) {
  if (!test::hasMethod("quadrature")) GTEST_SKIP() << "quadrature is not in this build";
  const Ran ran = runStep("sampling-closed");
  const StepResult& r = ran.result;
  EXPECT_EQ(ran.formFactorComputations, 1);  // the reference's F; the runs trace lines
  // "every variant shoots the same rays"; the row sums are still estimated.
  for (const std::string v : {"control-variate", "quasi-monte-carlo"})
    EXPECT_EQ(*r.value("rays." + v), *r.value("rays.monte-carlo")) << v;
  EXPECT_EQ(*r.value("rowsum-rays"), 256.0 * static_cast<double>(r.mesh.size()));
  // "the largest gain of the three", and a win with the row sums counted.
  EXPECT_GT(*r.value("gain.control-variate"), *r.value("gain.quasi-monte-carlo"));
  EXPECT_GT(*r.value("gain.quasi-monte-carlo"), 1.0);
  EXPECT_LT(*r.value("error-ratio.control-variate"), 0.85);
  // "The fitted slopes ... are alike".
  const double plain = *r.value("slope.monte-carlo"), control = *r.value("slope.control-variate");
  EXPECT_NEAR(plain, -0.5, 0.1);
  EXPECT_NEAR(control, plain, 0.1);
}

}  // namespace
}  // namespace rt::lesson
