// The error colouring of the scene view: relative (default) and absolute measures, and their colour bars.
#include <gtest/gtest.h>

#include "viz/scene_view.h"

namespace rt::viz {
namespace {

TEST(SceneError, RelativeErrorDividesByTheReference) {
  RgbField reference(3, 3), B(3, 3);
  reference << 10, 10, 10, 2, 4, 6, 1, 1, 1;
  B << 11, 9, 10, 2, 4, 3, 1, 1, 1;
  const Eigen::VectorXd absolute = absoluteError(B, reference);
  const Eigen::VectorXd relative = relativeError(B, reference);
  EXPECT_NEAR(absolute[0], 2.0 / 3, 1e-14);
  EXPECT_NEAR(relative[0], (2.0 / 3) / 10, 1e-14);
  EXPECT_NEAR(absolute[1], 1.0, 1e-14);
  EXPECT_NEAR(relative[1], 1.0 / 4, 1e-14);  // mean |dB| 1 over mean B_ref 4
  EXPECT_EQ(relative[2], 0.0);
}

TEST(SceneError, AZeroReferenceGivesALargeFiniteError) {
  RgbField reference(2, 3), B(2, 3);
  reference << 0, 0, 0, 100, 100, 100;
  B << 0.5, 0.5, 0.5, 100, 100, 100;
  const Eigen::VectorXd relative = relativeError(B, reference);
  // Floor: 1e-3 x the mean of the reference (50): 0.05, so 0.5 / 0.05 = 10.
  EXPECT_NEAR(relative[0], 10.0, 1e-12);
  EXPECT_TRUE(std::isfinite(relative[0]));
}

// Against the brightest reflecting element: the light (element 0, the brightest of all) does not set the
// scale, and a dim element's large ratio stays a small fraction.
TEST(SceneError, ErrorOfBrightestDividesByTheBrightestReflector) {
  Mesh mesh;
  mesh.emission = RgbField::Zero(3, 3);
  mesh.emission.row(0).setConstant(50);
  RgbField reference(3, 3), B(3, 3);
  reference << 1000, 1000, 1000, 20, 20, 20, 0.1, 0.1, 0.1;
  B << 1000, 1000, 1000, 22, 20, 18, 2.1, 2.1, 2.1;
  const Eigen::VectorXd brightest = errorOfBrightest(mesh, B, reference);
  EXPECT_EQ(brightest[0], 0.0);
  EXPECT_NEAR(brightest[1], (4.0 / 3) / 20, 1e-14);
  EXPECT_NEAR(brightest[2], 2.0 / 20, 1e-14);      // 10 %, where the per-element ratio is 20
  EXPECT_GT(relativeError(B, reference)[2], 5.0);  // the per-element ratio (floored at 1e-3 of the mean)
}

TEST(SceneError, MeasureNamesAndLegendTitles) {
  EXPECT_EQ(errorMeasureFromName("relative"), ErrorMeasure::Relative);
  EXPECT_EQ(errorMeasureFromName("absolute"), ErrorMeasure::Absolute);
  EXPECT_EQ(errorMeasureFromName("brightest"), ErrorMeasure::OfBrightest);
  EXPECT_THROW(errorMeasureFromName("percent"), std::invalid_argument);

  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  Element e;
  e.vertices = {0, 1, 2, 3};
  e.area = 1;
  e.normal = {0, 0, 1};
  e.centroid = {0.5, 0.5, 0};
  mesh.elements = {e, e};
  mesh.reflectance = RgbField::Constant(2, 3, 0.5);
  mesh.emission = RgbField::Zero(2, 3);
  SceneViewData data;
  data.reference = RgbField::Constant(2, 3, 10.0);
  data.B = data.reference;
  data.B(1, 0) = 16;  // mean |dB| = 2: relative 0.2
  SceneViewOptions options;
  options.colouring = SceneColouring::Error;
  ScenePaint paint = paintScene(mesh, data, options);
  EXPECT_NE(paint.legend.title.find("/ B_ref"), std::string::npos);
  EXPECT_NEAR(paint.legend.max, 0.2, 1e-12);
  options.errorMeasure = ErrorMeasure::Absolute;
  paint = paintScene(mesh, data, options);
  EXPECT_NE(paint.legend.title.find("W/m^2"), std::string::npos);
  EXPECT_NEAR(paint.legend.max, 2.0, 1e-12);
}

}  // namespace
}  // namespace rt::viz
