// Facts the lessons state in words, checked on the lessons' own steps (same scene, same parameters). When a
// lesson's text changes its claim, the test here changes with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/input_error.h"
#include "lesson/step_runner.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

class LessonFacts : public ::testing::Test {
 protected:
  void SetUp() override { test::ensureAnalyticMethod(); }
  // Runs the step that draws `figure`; skips the test when the build lacks a method the step needs.
  StepResult run(const std::string& lessonId, const std::string& figure) {
    lesson_ = test::shippedLesson(lessonId);
    const Step& step = test::stepWithFigure(lesson_, figure);
    for (const auto& m : {step.parameters.method, step.parameters.reference})
      if (!m.empty() && step.fields.count(m == step.parameters.method ? "method" : "reference") &&
          !test::hasMethod(m))
        skip_ = "form-factor method '" + m + "' is not in this build";
    for (const auto& m : step.parameters.methods)
      if (!test::hasMethod(m)) skip_ = "form-factor method '" + m + "' is not in this build";
    if (!skip_.empty()) return {};
    StepRunner runner(test::repoFolders().scenes);
    StepResult r = runner.run(lesson_, step);
    EXPECT_NO_THROW(resolvedText(lesson_, step, r));
    return r;
  }
  std::string skip_;
  Lesson lesson_;
};

#define RUN_OR_SKIP(var, lesson, figure)      \
  const StepResult var = run(lesson, figure); \
  if (!skip_.empty()) GTEST_SKIP() << skip_

TEST_F(LessonFacts, FurnaceGivesEOverOneMinusRho) {
  RUN_OR_SKIP(r, "rendering-equation", "furnace");
  const double expected = *r.value("E.floor") / (1.0 - *r.value("rho.floor"));
  for (const char* s : {"B.floor", "B.ceiling", "B.left", "B.right", "B.front", "B.back"})
    EXPECT_NEAR(*r.value(s), expected, 1e-9) << s;
}

TEST_F(LessonFacts, AClosedRoomAbsorbsWhatItEmits) {
  RUN_OR_SKIP(r, "rendering-equation", "balance");
  EXPECT_NEAR(*r.value("power.absorbed"), *r.value("power.emitted"), 1e-6 * *r.value("power.emitted"));
  EXPECT_NEAR(*r.value("B.floor"), *r.value("B.left"), 0.01 * *r.value("B.floor")) << "almost the same";
}

// The furnace's faces are Lambertian: the radiance they send into every direction is B / pi.
TEST_F(LessonFacts, TheFurnaceSendsRadianceBOverPi) {
  RUN_OR_SKIP(r, "rendering-equation", "furnace");
  EXPECT_NEAR(*r.value("L.floor"), *r.value("B.floor") / 3.14159265358979323846, 1e-12);
  EXPECT_NEAR(*r.value("L.floor"), *r.value("L.ceiling"), 1e-9);
}

// "Each face obeys B = E + rho H": the irradiance H = F B the step reports closes the equation on the floor
// (no emission) and on the ceiling (emission; it receives less than the floor).
TEST_F(LessonFacts, EachFaceIsItsEmissionPlusRhoTimesItsIrradiance) {
  RUN_OR_SKIP(r, "rendering-equation", "balance");
  EXPECT_EQ(*r.value("E.floor"), 0.0);
  EXPECT_GT(*r.value("E.ceiling"), 0.0);
  for (const char* s : {"floor", "ceiling", "left"}) {
    const std::string n = s;
    for (const char* c : {".r", ".g", ".b"})
      EXPECT_NEAR(*r.value("B." + n + c),
                  *r.value("E." + n + c) + *r.value("rho." + n + c) * *r.value("H." + n + c),
                  1e-6 * *r.value("B." + n + c))
          << s << c;
  }
  EXPECT_LT(*r.value("H.ceiling"), *r.value("H.floor"));
}

TEST_F(LessonFacts, ParallelAndPerpendicularSquaresExchangeAboutAFifth) {
  RUN_OR_SKIP(parallel, "form-factor", "parallel");
  RUN_OR_SKIP(perpendicular, "form-factor", "perpendicular");
  EXPECT_NEAR(*parallel.value("F.source.receiver"), 0.19982489569838738, 1e-9);
  EXPECT_NEAR(*perpendicular.value("F.source.receiver"), 0.20004377607540316, 1e-9);
}

TEST_F(LessonFacts, ReciprocityAndClosureInTheBox) {
  RUN_OR_SKIP(r, "form-factor", "reciprocity");
  EXPECT_NEAR(*r.value("area.floor") * *r.value("F.floor.back"),
              *r.value("area.back") * *r.value("F.back.floor"), 1e-9);
  EXPECT_LT(*r.value("reciprocity"), 1e-6);
  RUN_OR_SKIP(c, "form-factor", "closure");
  EXPECT_NEAR(*c.value("rowsum.min"), 1.0, 1e-6);
  EXPECT_NEAR(*c.value("rowsum.max"), 1.0, 1e-6);
}

TEST_F(LessonFacts, TheCeilingGetsNoDirectLightInTheCornellBox) {
  RUN_OR_SKIP(r, "local-vs-global", "local-global");
  EXPECT_NEAR(*r.value("Bdirect.ceiling"), 0.0, 1e-12);
  EXPECT_GT(*r.value("B.ceiling"), 0.0);
  EXPECT_NEAR(*r.value("Blocal.ceiling"), *r.value("ambient") * *r.value("rho.ceiling"),
              0.05 * *r.value("Blocal.ceiling"));
}

// local-vs-global, the room: the light is a rectangle (130 x 105 mm), not a square.
TEST_F(LessonFacts, TheCornellBoxLightIsARectangle) {
  RUN_OR_SKIP(r, "local-vs-global", "room");
  EXPECT_NEAR(*r.value("area.light"), 130.0 * 105.0, 1e-6);
  std::vector<double> edges;
  for (const Patch& patch : r.scene.patches)
    if (r.scene.surfaces[patch.surface].name == "light")
      for (std::size_t k = 0; k < patch.vertices.size(); ++k)
        edges.push_back((patch.vertices[(k + 1) % patch.vertices.size()] - patch.vertices[k]).norm());
  ASSERT_EQ(edges.size(), 4u);
  EXPECT_GT(*std::max_element(edges.begin(), edges.end()) / *std::min_element(edges.begin(), edges.end()),
            1.2);
}

// local-vs-global, what the constant misses: over the open box the ambient estimate is too large on average
// (it amplifies the reflected light as if none escaped); closed, the same estimate comes much closer. On the
// ceiling the two models agree, which is why one surface proves nothing.
TEST_F(LessonFacts, TheAmbientTermOvershootsInTheOpenBox) {
  RUN_OR_SKIP(r, "local-vs-global", "bleeding");
  ASSERT_TRUE(r.F);
  EXPECT_LT(r.F->rowwise().sum().minCoeff(), 0.99) << "light escapes through the open front";
  const double local = *r.value("Blocal.mean"), global = *r.value("B.mean");
  EXPECT_GT(local, 1.1 * global);
  EXPECT_NEAR(*r.value("Blocal.ceiling"), *r.value("B.ceiling"), 0.1 * *r.value("B.ceiling"));

  Step closed = test::stepWithFigure(lesson_, "bleeding");
  closed.scene = "cornell-box-closed.json";
  StepRunner runner(test::repoFolders().scenes);
  const StepResult c = runner.run(lesson_, closed);
  EXPECT_LT(std::abs(*c.value("Blocal.mean") / *c.value("B.mean") - 1), 0.5 * (local / global - 1));
}

// gathering: the divisor 1 / (1 - rho_i F_ii) of the sweeps is 1, because no flat element sees itself.
TEST_F(LessonFacts, FlatElementsDoNotSeeThemselves) {
  RUN_OR_SKIP(r, "gathering", "jacobi");
  ASSERT_TRUE(r.F);
  EXPECT_EQ(r.F->diagonal().cwiseAbs().maxCoeff(), 0.0);
}

TEST_F(LessonFacts, GaussSeidelNeedsAboutHalfTheSweepsOfJacobi) {
  RUN_OR_SKIP(r, "gathering", "side-by-side");
  const double ratio = *r.value("iterations.jacobi") / *r.value("iterations.gauss-seidel");
  EXPECT_GT(ratio, 1.5);
  EXPECT_LT(ratio, 3.0);
  EXPECT_LT(*r.value("difference.gauss-seidel"), 1e-4) << "both reach the same solution";
}

TEST_F(LessonFacts, SpectralRadiusOfTheUniformCubeIsRho) {
  RUN_OR_SKIP(r, "radiosity-matrix", "spectral");
  EXPECT_NEAR(*r.value("spectral-radius"), 0.5, 1e-6);
  EXPECT_NEAR(*r.value("dominance"), 0.5, 1e-9);
  RUN_OR_SKIP(high, "numerical-stability", "rho-099");
  EXPECT_NEAR(*high.value("spectral-radius"), 0.99, 1e-5);
  EXPECT_GT(*high.value("sweeps-per-decade"), 200.0);
}

TEST_F(LessonFacts, HigherReflectanceNeedsMoreSweeps) {
  RUN_OR_SKIP(r, "numerical-stability", "rho-095");
  EXPECT_GT(*r.value("iterations.jacobi"), *r.value("iterations.gauss-seidel"));
  EXPECT_GT(*r.value("iterations.jacobi"), 200.0);  // (0.95)^k < 1e-8 needs k > 359 sweeps
  // Unit faces, nothing escapes: sum_i B_i A_i = E A / (1 - rho) = 20.
  double total = 0;
  for (const char* face : {"floor", "ceiling", "back", "front", "left", "right"})
    total += *r.value(std::string("B.") + face + ".jacobi");
  EXPECT_NEAR(total, 20.0 * *r.value("E.ceiling"), 1e-4);
}

TEST_F(LessonFacts, BouncesConvergeToTheSolution) {
  RUN_OR_SKIP(one, "cornell-box", "bounce-1");
  EXPECT_NEAR(*one.value("B.ceiling.bounce[1]"), 0.0, 1e-12) << "the ceiling cannot see the light";
  RUN_OR_SKIP(two, "cornell-box", "bounce-2");
  EXPECT_GT(*two.value("B.ceiling.bounce[2]"), 0.0);
  RUN_OR_SKIP(many, "cornell-box", "bounce-12");
  EXPECT_GT(*many.value("fraction[12]"), 0.95);
  EXPECT_LT(*many.value("fraction[1]"), *many.value("fraction[12]"));
  // "After {{iterations.bounces}} bounces": terms 0 (the emission) to that count are summed.
  EXPECT_EQ(*many.value("iterations.bounces"), static_cast<double>(many.bounceTerms.size() - 1));
  EXPECT_EQ(*many.value("iterations.bounces"), 12.0) << "the text quotes fraction[12]";
}

TEST_F(LessonFacts, TheAmbientTermBringsTheFirstShotsCloserToTheAnswer) {
  RUN_OR_SKIP(plain, "shooting", "ten-shots");
  RUN_OR_SKIP(ambient, "shooting", "ten-shots-ambient");
  RUN_OR_SKIP(converged, "shooting", "shots-against-sweeps");
  const double target =
      *converged.value("B.floor.gauss-seidel") + *converged.value("B.back_wall.gauss-seidel");
  const double withAmbient = *ambient.value("B.floor") + *ambient.value("B.back_wall");
  const double without = *plain.value("B.floor") + *plain.value("B.back_wall");
  EXPECT_LT(std::abs(withAmbient - target), std::abs(without - target));
}

// shooting, the first shots: every element of the light shoots once, then an element of the back wall, which
// receives more of the light than the floor (shaded by the blocks) and, unlike the red and green walls,
// reflects every colour well.
TEST_F(LessonFacts, TheLightShootsFirstThenTheBackWall) {
  RUN_OR_SKIP(r, "shooting", "ten-shots");
  double lightElements = 0;
  for (const auto& element : r.mesh.elements)
    lightElements += r.scene.surfaces[r.scene.patches[element.patch].surface].name == "light";
  EXPECT_EQ(*r.value("shots.light"), lightElements);
  EXPECT_EQ(*r.value("first-shot.light"), 1.0);
  EXPECT_EQ(*r.value("first-shot.back_wall"), lightElements + 1);
  EXPECT_EQ(*r.value("shots.light") + *r.value("shots.back_wall"), *r.value("iterations"));
  EXPECT_GT(*r.value("F.light.back_wall"), *r.value("F.light.floor"));
  for (const char* wall : {"left_wall", "right_wall"}) {
    EXPECT_GT(*r.value(std::string("F.light.") + wall), 0.9 * *r.value("F.light.back_wall")) << wall;
    EXPECT_LT(*r.value(std::string("rho.") + wall), 0.5 * *r.value("rho.back_wall")) << wall;
  }
}

// ray-casting, rays between two plates: the plate in between hides only part of the receiver.
TEST_F(LessonFacts, APlateInBetweenHidesOnlyPartOfTheReceiver) {
  RUN_OR_SKIP(r, "ray-casting", "rays");
  EXPECT_LT(*r.value("area.occluder_top"), *r.value("area.receiver"));
  EXPECT_GT(*r.value("F.source.receiver"), 0.05);
  EXPECT_LT(*r.value("F.source.receiver"), 0.19982489569838738) << "less than without the plate";
}

TEST_F(LessonFacts, MonteCarloErrorFallsWithSamples) {
  RUN_OR_SKIP(r, "ray-casting", "noise");
  EXPECT_LT(*r.value("error.montecarlo[4]"), *r.value("error.montecarlo[0]"));
  EXPECT_LT(*r.value("error.raycast[4]"), *r.value("error.raycast[0]"));
  // "A much steeper line": 256 times the points buy ray casting far more than Monte Carlo's factor of 16.
  EXPECT_LT(*r.value("error.raycast[4]") / *r.value("error.raycast[0]"),
            0.1 * *r.value("error.montecarlo[4]") / *r.value("error.montecarlo[0]"));
}

// runtime-error-lab, the Cornell box: the hemicube levels off, ray casting keeps improving, and the hybrid
// method beats ray casting at the same number (rays per 1 % of F against samples per pair).
TEST_F(LessonFacts, OnTheCornellBoxTheHemicubeLevelsOffAndTheHybridMethodLeads) {
  RUN_OR_SKIP(r, "runtime-error-lab", "cornell");
  EXPECT_GT(*r.value("error.hemicube[3]"), 0.5 * *r.value("error.hemicube[1]"));
  EXPECT_LT(*r.value("error.raycast[3]"), 0.5 * *r.value("error.raycast[1]"));
  for (int k = 0; k < 4; ++k) {
    const std::string index = "[" + std::to_string(k) + "]";
    EXPECT_LT(*r.value("error.hybrid" + index), *r.value("error.raycast" + index)) << k;
  }
}

// runtime-error-lab, the quadrature method swept by digits: every digit asked for lowers the error, and at
// 10^-6 per entry the matrix is within 1e-5 of the exact method's (relative RMS).
TEST_F(LessonFacts, TheQuadratureMethodsErrorFollowsTheDigitsAskedFor) {
  RUN_OR_SKIP(r, "runtime-error-lab", "quadrature");
  for (int k = 0; k < 5; ++k) EXPECT_EQ(*r.value("parameter.quadrature[" + std::to_string(k) + "]"), k + 2);
  for (int k = 1; k < 5; ++k)
    EXPECT_LT(*r.value("error.quadrature[" + std::to_string(k) + "]"),
              *r.value("error.quadrature[" + std::to_string(k - 1) + "]"))
        << k;
  EXPECT_LT(*r.value("error.quadrature[4]"), 1e-5);
}

// hierarchical: a looser link tolerance gives fewer leaves and fewer links.
TEST_F(LessonFacts, ALooserLinkToleranceGivesACoarserHierarchy) {
  RUN_OR_SKIP(fine, "hierarchical", "hierarchy");
  RUN_OR_SKIP(coarse, "hierarchical", "coarse-hierarchy");
  EXPECT_GT(*coarse.value("refine-tolerance"), *fine.value("refine-tolerance"));
  EXPECT_LT(*coarse.value("elements"), *fine.value("elements"));
  EXPECT_LT(*coarse.value("links"), *fine.value("links"));
}

// numerical-stability: the room with reflectance 0.99 is as white as the whitest diffuse standards.
TEST_F(LessonFacts, TheNearlySingularRoomReflectsLikeSpectralon) {
  RUN_OR_SKIP(r, "numerical-stability", "rho-099");
  EXPECT_NEAR(*r.value("rho.max"), 0.99, 1e-12);
}

// numerical-stability, "How far errors can grow": in a closed room of one reflectance the row-sum-norm
// condition number reaches its bound (1 + rho) / (1 - rho), and a row-sum error is amplified rho / (1 - rho)
// times; the 2-norm condition number is another, smaller number of the same growth.
TEST_F(LessonFacts, TheClosedWhiteRoomReachesTheConditionBound) {
  RUN_OR_SKIP(r, "numerical-stability", "rho-099");
  const double rho = *r.value("rho.max");
  EXPECT_NEAR(*r.value("condition.bound"), (1 + rho) / (1 - rho), 1e-6 * (1 + rho) / (1 - rho));
  EXPECT_NEAR(*r.value("condition.inf"), *r.value("condition.bound"), 1e-6 * *r.value("condition.bound"));
  EXPECT_NEAR(*r.value("row-sum-gain"), rho / (1 - rho), 1e-6 * rho / (1 - rho));
  EXPECT_LE(*r.value("condition"), *r.value("condition.inf") * (1 + 1e-9));
  // "A row-sum error of 1e-5": B = E / (1 - rho (1 + e)) against E / (1 - rho), for an even emission.
  const double e = 1e-5;
  const double change = (1 - rho) / (1 - rho * (1 + e)) - 1;
  EXPECT_NEAR(change / e, *r.value("row-sum-gain"), 0.01 * *r.value("row-sum-gain"));
}

// The derivations the Solving chapters give, checked on the runs they describe. A run's every iteration is
// kept (RunOptions::recordHistory), as the app keeps it to replay the run.
StepResult runWithHistory(const Lesson& lesson, const Step& step) {
  StepRunner runner(test::repoFolders().scenes, RunOptions{.recordHistory = true});
  return runner.run(lesson, step);
}

// gathering, @eq:gs-increase and @eq:gs-below: from its start B = E, Gauss-Seidel raises every element's
// radiosity in every channel sweep after sweep, and never above the solution it converges to.
TEST_F(LessonFacts, GaussSeidelOnlyRaisesTheRadiositiesAndStaysBelowTheSolution) {
  const Lesson lesson = test::shippedLesson("gathering");
  const Step& step = test::stepWithFigure(lesson, "gauss-seidel");
  const StepResult r = runWithHistory(lesson, step);
  EXPECT_NO_THROW(resolvedText(lesson, step, r));
  const auto& history = r.replay.history;
  ASSERT_GT(history.size(), 5u);
  const double scale = r.B.maxCoeff();
  RgbField previous = r.mesh.emission;
  for (const IterationRecord& sweep : history) {
    EXPECT_GE((sweep.B - previous).minCoeff(), -1e-12 * scale) << "sweep " << sweep.iteration;
    EXPECT_LE((sweep.B - r.B).maxCoeff(), 1e-12 * scale) << "sweep " << sweep.iteration;
    previous = sweep.B;
  }
}

// shooting, @eq:southwell-rate: after k shots the unshot power is at most (1 - (1 - rho_max s) / n)^k of the
// emitted power, s the largest total share a shot hands out, sum_j A_j F_ji / A_i: the row sum, at most 1,
// for reciprocal form factors. The lesson's room shot to convergence with the quadrature method's form
// factors, which are reciprocal to their tolerance (the hemicube's are not, as the lesson says).
TEST_F(LessonFacts, SouthwellsUnshotPowerFallsAtLeastGeometrically) {
  const Lesson lesson = test::shippedLesson("shooting");
  Step step = test::stepWithFigure(lesson, "ten-shots");
  step.parameters.iterations = 4000;
  step.parameters.method = "quadrature";
  const StepResult r = runWithHistory(lesson, step);
  ASSERT_TRUE(r.F);
  const auto& history = r.replay.history;
  ASSERT_GT(history.size(), 1000u);
  const Eigen::VectorXd A = r.mesh.areas();
  const auto n = static_cast<double>(A.size());
  double share = 1.0;
  for (Eigen::Index i = 0; i < A.size(); ++i) share = std::max(share, r.F->col(i).dot(A) / A(i));
  EXPECT_LT(share, 1.01) << "the shares a shot hands out sum to about 1";
  const double rate = 1.0 - (1.0 - r.mesh.reflectance.maxCoeff() * share) / n;
  ASSERT_LT(rate, 1.0);
  const double emitted = history.front().emittedPower;
  for (const IterationRecord& shot : history)
    EXPECT_LE(shot.unshotPower, std::pow(rate, shot.iteration) * emitted * (1 + 1e-9))
        << "shot " << shot.iteration;
  // The bound is loose: the run is far below it after a sweep's worth of shots.
  const IterationRecord& sweep = history[static_cast<std::size_t>(n) - 1];
  EXPECT_LT(sweep.unshotPower, 0.5 * std::pow(rate, sweep.iteration) * emitted);
}

// radiosity-matrix, @eq:spectral-bound: the spectral radius of rho F is at most its largest row sum, which is
// at most the largest reflectance; equal in the uniform closed cube, below both in the open Cornell box.
TEST_F(LessonFacts, TheSpectralRadiusIsAtMostTheLargestRowSumAndReflectance) {
  RUN_OR_SKIP(cube, "radiosity-matrix", "spectral");
  const double cubeRowSum = 1.0 - *cube.value("dominance");
  EXPECT_NEAR(*cube.value("spectral-radius"), cubeRowSum, 1e-6);
  EXPECT_NEAR(cubeRowSum, *cube.value("rho.max"), 1e-9);
  RUN_OR_SKIP(room, "radiosity-matrix", "cornell");
  const double roomRowSum = 1.0 - *room.value("dominance");
  EXPECT_LE(*room.value("spectral-radius"), roomRowSum + 1e-9);
  EXPECT_LE(roomRowSum, *room.value("rho.max") + 1e-9);
  EXPECT_LT(*room.value("spectral-radius"), 0.95 * *room.value("rho.max")) << "well below it";
}

}  // namespace
}  // namespace rt::lesson
