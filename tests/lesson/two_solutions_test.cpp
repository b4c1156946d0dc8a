// The pathtrace stage and the facts the lesson "Two solutions of one equation" states about its numbers,
// checked on the lesson's own steps: the two-pass image is closer to the path-traced one than the radiosity
// image, the path tracer's noise falls as 1/sqrt(paths), and the steps of one lesson trace their pictures
// once.
#include <gtest/gtest.h>

#include <cmath>

#include "lesson/step_runner.h"
#include "lesson/traced_pictures.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

TEST(LogLogSlope, IsTheExponentOfAPowerLaw) {
  EXPECT_NEAR(logLogSlope({1, 4, 16, 64}, {1, 0.5, 0.25, 0.125}), -0.5, 1e-12);
  EXPECT_NEAR(logLogSlope({2, 3, 5}, {8, 27, 125}), 3.0, 1e-12);
  EXPECT_EQ(logLogSlope({1}, {1}), 0.0) << "one point has no slope";
  EXPECT_EQ(logLogSlope({1, 0, -1}, {1, 2, 3}), 0.0) << "points off the log scale are left out";
}

class TwoSolutions : public ::testing::Test {
 protected:
  void SetUp() override {
    test::ensureAnalyticMethod();
    lesson_ = test::shippedLesson("two-solutions");
  }
  Lesson lesson_;
};

TEST_F(TwoSolutions, TheTwoPassImageIsCloserToThePathTracedOneAndNoiseFallsAsOneOverRootPaths) {
  StepRunner runner(test::repoFolders().scenes);
  const Step& step = test::stepWithFigure(lesson_, "two-pass");
  const StepResult r = runner.run(lesson_, step);
  EXPECT_NO_THROW(resolvedText(lesson_, step, r));
  ASSERT_TRUE(r.pictures);
  const int size = step.parameters.imageSize;
  EXPECT_EQ(r.pictures->pathTraced.B.width, size);
  EXPECT_EQ(r.pictures->twoPass.height, size);
  EXPECT_GT(r.pictures->mean, 0) << "the path-traced image is not black";

  // "the two-pass picture differs by less than the radiosity picture", with and without the noise.
  EXPECT_LT(*r.value("rms.two-pass"), *r.value("rms.radiosity"));
  EXPECT_LT(*r.value("error.two-pass"), *r.value("error.radiosity"));
  // "the mesh's error": the radiosity image's own error is larger than the path tracer's noise.
  EXPECT_GT(*r.value("error.radiosity"), *r.value("noise.path-traced"));
  // "a line of slope -1/2"; sixteen times the paths give a quarter of the noise.
  EXPECT_NEAR(*r.value("noise-slope"), -0.5, 0.1);
  EXPECT_NEAR(*r.value("noise[2]") / *r.value("noise[0]"), 0.25, 0.06);
  EXPECT_EQ(*r.value("noise-paths[2]"), 16 * *r.value("noise-paths[0]"));
  // The tracer's own standard errors tell the noise they have (within a third).
  for (const NoisePoint& p : r.pictures->noise) EXPECT_NEAR(p.reported / p.measured, 1.0, 0.35) << p.paths;
  for (const char* t : {"seconds.solve", "seconds.trace", "seconds.two-pass"}) EXPECT_GT(*r.value(t), 0) << t;
  EXPECT_GT(*r.value("rays.path-traced"), *r.value("pixels") * *r.value("paths"));
  // "the mesh is cut first where the blocks stand on the floor": both blocks' footprints, four sides each.
  EXPECT_EQ(*r.value("contact-segments"), 8);
}

TEST_F(TwoSolutions, StepsShowingOtherViewsOfTheSamePicturesTraceThemOnce) {
  StepRunner runner(test::repoFolders().scenes, RunOptions{.quick = true});
  const StepResult first = runner.run(lesson_, test::stepWithFigure(lesson_, "two-solutions"));
  const StepResult second = runner.run(lesson_, test::stepWithFigure(lesson_, "noise"));
  ASSERT_TRUE(first.pictures);
  EXPECT_EQ(first.pictures, second.pictures);
  EXPECT_EQ(*first.value("rms.radiosity"), *second.value("rms.radiosity"));
  // Another seed is another picture.
  Step other = test::stepWithFigure(lesson_, "noise");
  other.parameters.seed = 7;
  const StepResult third = runner.run(lesson_, other);
  EXPECT_NE(third.pictures, first.pictures);
  EXPECT_NE(*third.value("rms.radiosity"), *first.value("rms.radiosity"));
}

TEST_F(TwoSolutions, QuickRunsKeepTheImagesSmall) {
  StepRunner runner(test::repoFolders().scenes, RunOptions{.quick = true});
  const StepResult r = runner.run(lesson_, test::stepWithFigure(lesson_, "difference"));
  ASSERT_TRUE(r.pictures);
  EXPECT_LE(r.pictures->radiosity.width, 48);
  EXPECT_LE(*r.value("paths"), 64);
}

}  // namespace
}  // namespace rt::lesson
