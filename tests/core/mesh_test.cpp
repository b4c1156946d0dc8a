#include "core/mesh.h"

#include <gtest/gtest.h>

#include "core/polygon.h"

namespace rt {
namespace {

Scene unitSquareScene() {
  Scene s;
  s.materials.push_back({"white", Rgb(0.5, 0.5, 0.5), Rgb(1, 1, 1)});
  s.surfaces.push_back({"square", 0});
  Patch p;
  p.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  p.normal = Vec3(0, 0, 1);
  p.area = 1;
  p.surface = 0;
  s.patches.push_back(p);
  Patch t;
  t.vertices = {Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(0, 2, 1)};
  t.normal = Vec3(0, 0, 1);
  t.area = 2;
  t.surface = 0;
  s.patches.push_back(t);
  return s;
}

TEST(Mesh, AFarAwayPolygonDoesNotWeldTheCornersOfSmallElements) {
  // Found by fuzzing: one coordinate of 1e10 among unit-sized patches made the welding tolerance (relative to
  // the scene) larger than the small elements, which then lost their corners and their planarity.
  Scene s = unitSquareScene();
  s.patches[1].vertices = {Vec3(0, 0, 1), Vec3(2e10, 0, 1), Vec3(0, 2, 1)};
  s.patches[1].area = 2e10;
  MeshOptions options;
  options.mode = MeshOptions::Mode::Count;
  options.count = 4;
  const Mesh m = buildMesh(s, options);
  double area = 0;
  for (const Element& e : m.elements)
    if (e.patch == 0) {
      EXPECT_NEAR(e.area, 1.0 / 16, 1e-12);
      area += e.area;
    }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_EQ(m.vertices.size(), 25u + 15u);  // 5 x 5 grid on the square, 15 barycentric points on the triangle
}

TEST(Mesh, NoSubdivisionKeepsOneElementPerPatchInOrder) {
  const Mesh m = buildMesh(unitSquareScene());
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m.elements[0].patch, 0);
  EXPECT_EQ(m.elements[1].patch, 1);
  EXPECT_DOUBLE_EQ(m.elements[0].area, 1.0);
  EXPECT_DOUBLE_EQ(m.elements[1].area, 2.0);
}

TEST(Mesh, CountSubdivisionPreservesAreaAndSharesVertices) {
  MeshOptions o;
  o.mode = MeshOptions::Mode::Count;
  o.count = 4;
  const Mesh m = buildMesh(unitSquareScene(), o);
  ASSERT_EQ(m.size(), 32u);  // 16 quads + 16 triangles
  double square = 0, triangle = 0;
  for (const Element& e : m.elements) (e.patch == 0 ? square : triangle) += e.area;
  EXPECT_NEAR(square, 1.0, 1e-14);
  EXPECT_NEAR(triangle, 2.0, 1e-14);
  // 5 x 5 grid on the square, 15 grid points on the triangle.
  EXPECT_EQ(m.vertices.size(), 25u + 15u);
  // An interior element of the square has 4 edge neighbours.
  EXPECT_EQ(m.edgeNeighbours(5).size(), 4u);
  // A corner element has 2.
  EXPECT_EQ(m.edgeNeighbours(0).size(), 2u);
}

TEST(Mesh, MaxEdgeBoundsEveryEdge) {
  MeshOptions o;
  o.mode = MeshOptions::Mode::MaxEdge;
  o.maxEdge = 0.3;
  const Mesh m = buildMesh(unitSquareScene(), o);
  for (std::size_t e = 0; e < m.size(); ++e)
    EXPECT_LE(maxEdgeLength(m.polygon(static_cast<int>(e))), 0.3 + 1e-12);
}

TEST(Mesh, GeometryHashIgnoresMaterials) {
  Scene s = unitSquareScene();
  const Mesh a = buildMesh(s);
  s.materials[0].emission = Rgb(5, 5, 5);
  const Mesh b = buildMesh(s);
  EXPECT_EQ(a.geometryHash(), b.geometryHash());
  EXPECT_NE(a.emission(0, 0), b.emission(0, 0));
}

TEST(Mesh, RejectsImpossibleOptions) {
  MeshOptions o;
  o.mode = MeshOptions::Mode::Count;
  o.count = 0;
  EXPECT_THROW(buildMesh(unitSquareScene(), o), InputError);
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

TEST(DefaultMesh, TheLargestRoundEdgeThatGivesTheElementsAsked) {
  Scene s;
  s.materials.push_back({"grey", Rgb(0.5, 0.5, 0.5), Rgb(1, 1, 1)});
  s.surfaces.push_back({"square", 0});
  Patch p;
  p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  p.normal = Vec3(0, 0, 1);
  p.area = 1;
  p.surface = 0;
  s.patches.push_back(p);
  // A unit square: 100 elements need 10 divisions, which every edge from 0.1 to just under 1/9 gives; the
  // largest with two digits is 0.11 (0.12 gives 9 x 9 = 81).
  const MeshOptions chosen = defaultMeshOptions(s, 100);
  ASSERT_EQ(chosen.mode, MeshOptions::Mode::MaxEdge);
  EXPECT_NEAR(chosen.maxEdge, 0.11, 1e-12);
  EXPECT_EQ(estimatedElementCount(s, chosen), 100);
  EXPECT_EQ(buildMesh(s, chosen).size(), 100u);
  // A scene with as many patches as asked keeps one element per patch.
  EXPECT_EQ(defaultMeshOptions(s, 1).mode, MeshOptions::Mode::None);
}

}  // namespace
}  // namespace rt
