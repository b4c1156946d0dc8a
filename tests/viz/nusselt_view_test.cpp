// The Nusselt construction: the projected area / pi converges to the exact point-to-polygon form factor.
#include <gtest/gtest.h>

#include <cmath>

#include "support/test_paths.h"
#include "viz/nusselt_view.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

TEST(NusseltView, DiskAreaMatchesTheContourIntegral) {
  // A unit square parallel to the base at height 1, centred over the point: four corner rectangles of
  // Howell's differential-to-rectangle case with a = b = 0.5: F = (4/2pi) 2 (a/sqrt(1+a^2))
  // atan(a/sqrt(1+a^2)) = 0.2394564...
  const Polygon square = {{-0.5, -0.5, 1}, {-0.5, 0.5, 1}, {0.5, 0.5, 1}, {0.5, -0.5, 1}};
  const NusseltConstruction c = nusseltConstruction(Vec3::Zero(), Vec3::UnitZ(), square, 256);
  const double a = 0.5 / std::sqrt(1.25);
  EXPECT_NEAR(c.exact, 4.0 / (2 * M_PI) * 2 * a * std::atan(a), 1e-12);
  EXPECT_NEAR(c.diskAreaFraction, c.exact, 1e-4);
  EXPECT_NEAR(c.u.dot(c.normal), 0.0, 1e-12);
  EXPECT_NEAR(c.u.cross(c.v).dot(c.normal), 1.0, 1e-12);
  for (const Vec3& d : c.onHemisphere) EXPECT_NEAR(d.norm(), 1.0, 1e-12);
}

TEST(NusseltView, PartlyBehindTheHorizonIsClipped) {
  // A vertical square straddling the tangent plane: only the upper half counts.
  const Polygon wall = {{-0.5, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5}, {-0.5, 1, 0.5}};
  const NusseltConstruction c = nusseltConstruction(Vec3::Zero(), Vec3::UnitZ(), wall, 256);
  EXPECT_EQ(c.visible.size(), 4u);
  for (const Vec3& p : c.visible) EXPECT_GE(p.z(), -1e-12);
  EXPECT_NEAR(c.diskAreaFraction, c.exact, 2e-4);
  EXPECT_GT(c.exact, 0.0);
}

TEST(NusseltView, FiguresInEveryFormat) {
  const Polygon square = {{-0.5, -0.5, 1}, {-0.5, 0.5, 1}, {0.5, 0.5, 1}, {0.5, -0.5, 1}};
  const NusseltConstruction c = nusseltConstruction(Vec3::Zero(), Vec3::UnitZ(), square);
  NusseltViewOptions o;
  o.size = {400, 400, 96};
  const std::string dir = test::scratchDir("nusselt_view");
  writeNusseltDiskFigure(c, o, dir + "/disk.svg");
  writeNusseltDiskFigure(c, o, dir + "/disk.png");
  writeNusseltHemisphereFigure(c, o, dir + "/hemisphere.png");
  const std::string svg = vizt::readFile(dir + "/disk.svg");
  EXPECT_TRUE(svg.find("<polygon") != std::string::npos || svg.find("<path") != std::string::npos);
  EXPECT_EQ(svg.find("<image"), std::string::npos);
  EXPECT_GT(vizt::pngStats(dir + "/disk.png").stddev, 20.0);
  EXPECT_GT(vizt::pngStats(dir + "/hemisphere.png").stddev, 20.0);
}

}  // namespace
}  // namespace rt::viz
