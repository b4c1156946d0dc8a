// The step runner: what each stage computes, the form-factor cache, placeholders filled from results, errors
// at the line of the parameter at fault.
#include "lesson/step_runner.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "lesson/lesson_parser.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

class StepRunnerTest : public ::testing::Test {
 protected:
  void SetUp() override { test::ensureAnalyticMethod(); }
  std::string scenes = test::repoFolders().scenes;
};

const char* kFurnace = R"(---
title: Furnace
order: 1
---
## Solve
```step
scene: furnace-cube.json
stage: solve
method: analytic
solver: gauss-seidel
tolerance: 1e-12
```
B = {{B.floor:6}} on the floor after {{iterations}} sweeps.

## Darker walls
```step
scene: furnace-cube.json
stage: solve
method: analytic
solver: direct
reflectance.floor: 0.25
reflectance.ceiling: 0.25
reflectance.back: 0.25
reflectance.front: 0.25
reflectance.left: 0.25
reflectance.right: 0.25
```
Now {{B.ceiling:6}}.

## Brighter light
```step
scene: furnace-cube.json
stage: matrix
method: analytic
light-scale: 3
highlight: 5
```
Radius {{spectral-radius:4}}, {{unknown.value}}.
)";

TEST_F(StepRunnerTest, FurnaceStepsGiveEOverOneMinusRhoAndShareOneF) {
  const Lesson lesson = parseLesson(kFurnace, "furnace", "furnace.md");
  StepRunner runner(scenes);
  const StepResult a = runner.run(lesson, lesson.steps[0]);
  EXPECT_NEAR(*a.value("B.floor"), 2.0, 1e-9);
  EXPECT_NEAR(*a.value("B[3]"), 2.0, 1e-9);
  EXPECT_NEAR(*a.value("F[0][0]"), 0.0, 1e-15);
  EXPECT_NEAR(*a.value("rowsum[2]"), 1.0, 1e-9);
  EXPECT_GT(*a.value("iterations"), 1.0);
  EXPECT_EQ(resolvedText(lesson, lesson.steps[0], a).substr(0, 20), "B = 2 on the floor a");

  // Only the materials change: B = E / (1 - rho) = 1 / 0.75, and F comes from the cache.
  const StepResult b = runner.run(lesson, lesson.steps[1]);
  EXPECT_NEAR(*b.value("B.ceiling"), 1.0 / 0.75, 1e-9);
  EXPECT_NEAR(*b.value("rho.left"), 0.25, 1e-15);

  // Only the light changes: still the same F. Spectral radius of rho F with closed rows = rho.
  const StepResult c = runner.run(lesson, lesson.steps[2]);
  EXPECT_NEAR(*c.value("spectral-radius"), 0.5, 1e-6);
  EXPECT_NEAR(*c.value("E.floor"), 3.0, 1e-12);
  EXPECT_GT(*c.value("dominance"), 0.0);
  EXPECT_EQ(c.highlighted, std::vector<int>{5});
  EXPECT_EQ(runner.formFactorComputations(), 1);

  try {
    resolvedText(lesson, lesson.steps[2], c);
    FAIL() << "unknown placeholder accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 38);
    EXPECT_NE(std::string(e.what()).find("F[i][j]"), std::string::npos) << "lists what is available";
  }
}

TEST_F(StepRunnerTest, SurfaceFormFactorsAreAreaWeightedAndReciprocal) {
  const Lesson lesson = parseLesson(R"(---
title: Box
order: 1
---
## F
```step
scene: box-1x2x3.json
stage: formfactors
method: analytic
subdivide: 2
```
)",
                                    "box", "box.md");
  StepRunner runner(scenes);
  const StepResult r = runner.run(lesson, lesson.steps[0]);
  EXPECT_EQ(*r.value("elements"), 24.0);
  EXPECT_NEAR(*r.value("area.floor"), 3.0, 1e-12);
  EXPECT_NEAR(*r.value("area.back") * 1.0, 2.0, 1e-12);
  EXPECT_NEAR(*r.value("area.floor") * *r.value("F.floor.back"),
              *r.value("area.back") * *r.value("F.back.floor"), 1e-9);
  EXPECT_NEAR(*r.value("rowsum.floor"), 1.0, 1e-6);
  EXPECT_NEAR(*r.value("rowsum.min"), 1.0, 1e-6);
}

TEST_F(StepRunnerTest, BouncesAddUpToTheSolution) {
  const Lesson lesson = parseLesson(R"(---
title: Bounces
order: 1
---
## B
```step
scene: furnace-cube-one-light.json
stage: bounces
method: analytic
bounces: 40
```
)",
                                    "b", "b.md");
  StepRunner runner(scenes);
  const StepResult r = runner.run(lesson, lesson.steps[0]);
  // rho = 0.5, closed: bounce k carries 0.5^k of the emitted power.
  EXPECT_NEAR(*r.value("bounce[0]"), 1.0, 1e-12);
  EXPECT_NEAR(*r.value("bounce[1]"), 0.5, 1e-9);
  EXPECT_NEAR(*r.value("bounce[3]"), 0.125, 1e-9);
  EXPECT_NEAR(*r.value("fraction[40]"), 1.0, 1e-9);
  EXPECT_NEAR(*r.value("amplification"), 2.0, 1e-9);
  EXPECT_NEAR(*r.value("B.floor.bounce[40]"), *r.value("Bexact.floor"), 1e-9);
  EXPECT_NEAR(*r.value("B.ceiling.bounce[0]"), 1.0, 1e-12);  // only the light glows before any bounce
  EXPECT_EQ(r.runs.at(0).residuals.size(), 41u);
}

TEST_F(StepRunnerTest, RuntimeErrorsNameTheLine) {
  const Lesson lesson = parseLesson(R"(---
title: Bad
order: 1
---
## Too far
```step
scene: parallel-squares.json
stage: formfactors
method: analytic
from: 7
```
)",
                                    "bad", "bad.md");
  StepRunner runner(scenes);
  try {
    runner.run(lesson, lesson.steps[0]);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 10);
    EXPECT_NE(std::string(e.what()).find("element 7"), std::string::npos);
  }
}

TEST_F(StepRunnerTest, TextStepsComputeNothing) {
  const Lesson lesson = parseLesson(
      "---\ntitle: T\norder: 1\n---\n## T\n```step\nstage: text\n```\nNo numbers.\n", "t", "t.md");
  StepRunner runner(scenes);
  const StepResult r = runner.run(lesson, lesson.steps[0]);
  EXPECT_FALSE(r.F);
  EXPECT_EQ(resolvedText(lesson, lesson.steps[0], r), "No numbers.\n");
}

}  // namespace
}  // namespace rt::lesson
