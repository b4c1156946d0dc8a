// The quadrature method has no silent limits: occluders of any corner count (prisms and two-sided discs of
// 3 to 200 sides), a hundred occluders, and the clipped pieces and cones they make, each against an
// independent reference (occluder_room.h) within the method's tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/pair_matrix.h"
#include "core/formfactor/quadrature/quadrature_pair.h"
#include "core/formfactor/quadrature/quadrature_scene.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/shaft_culling.h"
#include "core/geometry/plane_clip.h"
#include "occluder_room.h"

namespace rt {
namespace {

constexpr double kTolerance = 1e-5;  // the method's default

// F_ij by the quadrature method's own pair (as its matrix computes it, from the smaller element), without
// the rest of the matrix.
double quadratureEntry(const Mesh& mesh, int i, int j, double tolerance = kTolerance) {
  const ShaftCulling shafts(mesh);
  const QuadratureScene scene(mesh, shafts);
  QuadraturePair pair(scene, tolerance);
  return fromSmallerElement(mesh, i, j, [&](int a, int b) { return pair(a, b, i); }).value;
}

// The reference on two grids over the light; their difference bounds its own error, and must be far below
// the tolerance for the comparison to mean anything.
double reference(const Mesh& mesh, int light, int receiver, const std::vector<Polygon>& occluders) {
  const Polygon l = mesh.polygon(light), r = mesh.polygon(receiver);
  const double coarse = test::referenceLightToFloor(l, r, occluders, 12);
  const double fine = test::referenceLightToFloor(l, r, occluders, 24);
  EXPECT_LT(std::abs(fine - coarse), 0.1 * kTolerance) << "the reference has not converged";
  return fine;
}

Mesh wholePatches(const Scene& scene) {
  return buildMesh(scene, MeshOptions{});
}

int onlyElement(const Mesh& mesh, int patch) {
  const std::vector<int> elements = test::elementsOf(mesh, patch);
  EXPECT_EQ(elements.size(), 1u);
  return elements.front();
}

class QuadratureOccluderCorners : public ::testing::TestWithParam<int> {};

// A prism of n sides standing on the floor under the light: its caps are occluders of n corners (more than
// the 28 the clipper once took: those were left out, and the floor saw through the prism's top), and its
// silhouette from the light has n + 2 edges or so.
TEST_P(QuadratureOccluderCorners, PrismStandingOnTheFloor) {
  const int n = GetParam();
  Scene scene = test::litRoom();
  const Polygon corners = test::addPrism(scene, n, 0.5, 0.5, 0.15, 0.0, 0.3);
  const Mesh mesh = wholePatches(scene);
  const int light = onlyElement(mesh, test::kLightPatch), floor = onlyElement(mesh, test::kFloorPatch);
  const double expected = reference(mesh, light, floor, {corners});
  const double F = quadratureEntry(mesh, light, floor);
  EXPECT_NEAR(F, expected, kTolerance) << n << " sides";
  // The prism hides a good part: an occluder left out would show as the unoccluded value.
  const double unoccluded = test::referenceLightToFloor(mesh.polygon(light), mesh.polygon(floor), {}, 4);
  EXPECT_LT(F, unoccluded - 0.01);
}

// A floating disc of n sides, seen from both sides (two coincident polygons back to back).
TEST_P(QuadratureOccluderCorners, TwoSidedDiscFloatingUnderTheLight) {
  const int n = GetParam();
  Scene scene = test::litRoom();
  const Polygon corners = test::addDisc(scene, n, 0.5, 0.5, 0.12, 0.5);
  const Mesh mesh = wholePatches(scene);
  const int light = onlyElement(mesh, test::kLightPatch), floor = onlyElement(mesh, test::kFloorPatch);
  const double expected = reference(mesh, light, floor, {corners});
  EXPECT_NEAR(quadratureEntry(mesh, light, floor), expected, kTolerance) << n << " sides";
}

INSTANTIATE_TEST_SUITE_P(Sides, QuadratureOccluderCorners, ::testing::Values(3, 8, 29, 64, 200),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return std::to_string(info.param) + "Sides";
                         });

// A hundred closed hexagonal prisms floating low over the floor, in a grid whose shadows never meet: more
// solids than the shadows-apart table was once kept for (16), and more occluders than any array holds.
TEST(QuadratureOccluderCount, AHundredPrisms) {
  Scene scene = test::litRoom();
  std::vector<Polygon> bodies;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      bodies.push_back(test::addPrism(scene, 6, 0.095 + 0.09 * i, 0.095 + 0.09 * j, 0.015, 0.02, 0.05));
  const Mesh mesh = wholePatches(scene);
  const int light = onlyElement(mesh, test::kLightPatch), floor = onlyElement(mesh, test::kFloorPatch);
  const double expected = reference(mesh, light, floor, bodies);
  EXPECT_NEAR(quadratureEntry(mesh, light, floor), expected, kTolerance);
}

// The room of the method's notes: a 40-sided prism standing on the floor and a 36-sided disc floating
// beside it, their shadows on the floor apart.
struct PrismAndDisc {
  Scene scene = test::litRoom();
  std::vector<Polygon> bodies;
  PrismAndDisc() {
    bodies.push_back(test::addPrism(scene, 40, 0.3, 0.3, 0.12, 0.0, 0.3));
    bodies.push_back(test::addDisc(scene, 36, 0.68, 0.68, 0.08, 0.4));
  }
};

TEST(QuadraturePrismAndDiscRoom, WholePatchesMatchTheReferenceAndCloseTheLightsRow) {
  const PrismAndDisc room;
  const Mesh mesh = wholePatches(room.scene);
  const int light = onlyElement(mesh, test::kLightPatch), floor = onlyElement(mesh, test::kFloorPatch);
  FormFactorOptions options;
  options.tolerance = kTolerance;
  const FormFactorMatrix F = test::runMethod("quadrature", mesh, options);
  const double expected = reference(mesh, light, floor, room.bodies);
  EXPECT_NEAR(F(light, floor), expected, kTolerance);
  // A closed room: the light's row sums to 1, each of its entries within the tolerance.
  EXPECT_NEAR(F.row(light).sum(), 1.0, kTolerance * static_cast<double>(mesh.size()));
  EXPECT_LE(F.rowwise().sum().maxCoeff(), 1.0 + kTolerance * static_cast<double>(mesh.size()));
}

TEST(QuadraturePrismAndDiscRoom, SmallMeshMatchesTheReferenceOnEveryFloorElement) {
  const PrismAndDisc room;
  MeshOptions options;
  options.mode = MeshOptions::Mode::Count;
  options.count = 3;
  const Mesh mesh = buildMesh(room.scene, options);
  const std::vector<int> lights = test::elementsOf(mesh, test::kLightPatch),
                         floors = test::elementsOf(mesh, test::kFloorPatch);
  ASSERT_EQ(lights.size(), 9u);
  ASSERT_EQ(floors.size(), 9u);
  const ShaftCulling shafts(mesh);
  const QuadratureScene scene(mesh, shafts);
  QuadraturePair pair(scene, kTolerance);
  for (int light : {lights.front(), lights[4]})
    for (int floor : floors) {
      const double F =
          fromSmallerElement(mesh, light, floor, [&](int a, int b) { return pair(a, b, light); }).value;
      const double expected =
          test::referenceLightToFloor(mesh.polygon(light), mesh.polygon(floor), room.bodies, 16);
      EXPECT_NEAR(F, expected, kTolerance) << "light element " << light << ", floor element " << floor;
    }
}

// The clipper's own polygons keep every corner, however many: a 200-gon clipped by a plane through it.
TEST(QuadratureClipCapacity, ClipKeepsEveryCornerPastTheInlineSize) {
  const Polygon disc = test::ngon(200, 0, 0, 1, 0);
  ConvexPolygon out;
  EXPECT_TRUE(clipToFront(disc.data(), 200, Vec3(-2, 0, 0), Vec3(1, 0, 0), 1e-12, out));
  EXPECT_EQ(out.count, 200);
  clipToFront(disc.data(), 200, Vec3(0, 0, 0), Vec3(1, 0, 0), 1e-12, out);
  EXPECT_GE(out.count, 101);  // the half in front, and the cut
  double area = 0;
  for (int k = 0; k < out.count; ++k) {
    const Vec3 &a = out.v[static_cast<std::size_t>(k)],
               &b = out.v[static_cast<std::size_t>((k + 1) % out.count)];
    area += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  EXPECT_NEAR(area, 0.5 * 100 * std::sin(2 * std::numbers::pi / 200), 1e-12);
  ConvexPolygon copy = out;  // copies and moves keep the heap part
  ConvexPolygon moved = std::move(copy);
  EXPECT_EQ(moved.count, out.count);
  EXPECT_EQ(moved.v[100].x(), out.v[100].x());
}

}  // namespace
}  // namespace rt
