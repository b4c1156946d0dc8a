// PenumbraRegion against brute force: a source panel it calls unshaded has every point see the whole
// receiver past the block (checked by clipping per point); the region holds every point that the clipping
// finds shaded; and a block reaching as high as the receiver makes no region at all.
#include "core/formfactor/quadrature/penumbra_region.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "core/box_solid.h"
#include "core/formfactor/quadrature/shadow_clipper.h"

namespace rt {
namespace {

ConvexPolygon square(double x0, double y0, double size, double z, bool up) {
  ConvexPolygon p;
  const std::array<Vec3, 4> corners{
      Vec3{x0, y0, z}, {x0 + size, y0, z}, {x0 + size, y0 + size, z}, {x0, y0 + size, z}};
  for (int k = 0; k < 4; ++k)
    p.v[static_cast<std::size_t>(k)] = corners[static_cast<std::size_t>(up ? k : 3 - k)];
  p.count = 4;
  return p;
}

TEST(PenumbraRegion, HoldsEveryShadedPointOfTheSourcesPlane) {
  const Box block = box({1.0, 1.2, 0.8}, {1.6, 1.7, 1.5});
  const std::vector<SolidPlanes> planes{block.planes};
  const std::vector<Vec3> centres{block.centre};
  const std::vector<OccluderPolygon> occluders = block.occluders();
  const ConvexPolygon receiver = square(0.5, 0.5, 2.0, 3.0, false);  // the ceiling, facing down
  PenumbraRegion region;
  const SolidShape& shape = block.shapes[0];
  ASSERT_TRUE(region.build(shape.corners.data(), static_cast<int>(shape.corners.size()), receiver.v.data(),
                           receiver.count, Vec3::Zero(), Vec3::UnitZ(), 1e-12));
  // Floor panels on a grid, some under the block's shadow, some far off to the side.
  int shaded = 0, clear = 0;
  for (double x0 = -3.0; x0 < 5.0; x0 += 0.5)
    for (double y0 = -3.0; y0 < 5.0; y0 += 0.5) {
      const ConvexPolygon source = square(x0, y0, 0.5, 0.0, true);
      const ShadowClipper clipper(source, Vec3::UnitZ(), receiver, -Vec3::UnitZ(), occluders, planes,
                                  &centres, &block.shapes);
      bool anyShade = false;
      for (double s = 0; s <= 1.0; s += 0.125)
        for (double t = 0; t <= 1.0; t += 0.125)
          anyShade |= clipper.hidden({x0 + 0.5 * s, y0 + 0.5 * t, 0.0}, clipper.occluders()) > 0;
      const bool meets = region.meets(source.v.data(), source.count);
      if (anyShade) {
        EXPECT_TRUE(meets) << x0 << ", " << y0;
      }
      shaded += anyShade;
      clear += !meets;
    }
  EXPECT_GT(shaded, 10);
  EXPECT_GT(clear, 100);  // most of the plane is outside the region
}

TEST(PenumbraRegion, NoRegionWhereTheBlockReachesTheReceiversHeight) {
  const Box block = box({1.0, 1.2, 0.0}, {1.6, 1.7, 2.0});
  // A wall element beside the block, lower than the block's top: seen from it, the block's top corners
  // project to infinity on the floor.
  const ConvexPolygon wall = polygon({{3, 0, 0.5}, {3, 3, 0.5}, {3, 3, 1.5}, {3, 0, 1.5}});
  PenumbraRegion region;
  const SolidShape& shape = block.shapes[0];
  EXPECT_FALSE(region.build(shape.corners.data(), static_cast<int>(shape.corners.size()), wall.v.data(),
                            wall.count, Vec3::Zero(), Vec3::UnitZ(), 1e-12));
  EXPECT_TRUE(region.meets(wall.v.data(), wall.count));  // no region: never rules anything out
}

}  // namespace
}  // namespace rt
