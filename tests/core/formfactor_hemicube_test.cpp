// Hemicube pieces (delta form factors, face buffers) and the Nusselt analog's projected outline.
#include <gtest/gtest.h>

#include <numeric>

#include "core/formfactor/analytic.h"
#include "core/formfactor/hemicube.h"
#include "core/formfactor/nusselt.h"
#include "formfactor_scenes.h"

namespace rt {
namespace {

double deltaSum(int resolution) {
  double sum = 0;
  for (int f = 0; f < 5; ++f) {
    const auto& d = deltaFormFactors(resolution, static_cast<HemicubeFace>(f));
    sum += std::accumulate(d.begin(), d.end(), 0.0);
  }
  return sum;
}

// Each delta form factor is the exact form factor of its pixel, and the pixels tile the hemisphere: the sum
// is 1 up to the rounding of ~3 res^2 additions. Every resolution from 2 to 128, then a spread up to 512 (all
// 511 resolutions would take ~20 s).
TEST(Hemicube, DeltaFormFactorsSumToOneAtEveryResolution) {
  for (int r = 2; r <= 128; ++r) EXPECT_NEAR(deltaSum(r), 1.0, 1e-12) << r;
  for (int r : {129, 200, 255, 256, 257, 333, 400, 511, 512}) EXPECT_NEAR(deltaSum(r), 1.0, 1e-11) << r;
  EXPECT_THROW(deltaFormFactors(1, HemicubeFace::Top), std::invalid_argument);
}

TEST(Hemicube, DeltaFormFactorsApproachTheDifferentialFormula) {
  // Away from the edges a pixel's exact form factor tends to the classic cos^2 / (pi r^4) dA expression.
  const int res = 256;
  const auto& top = deltaFormFactors(res, HemicubeFace::Top);
  const int row = res / 2 + 10, column = res / 2 - 30;
  const double x = -1 + (column + 0.5) * 2.0 / res, y = -1 + (row + 0.5) * 2.0 / res;
  const double classic = (2.0 / res) * (2.0 / res) / (std::numbers::pi * std::pow(x * x + y * y + 1, 2));
  EXPECT_NEAR(top[row * res + column], classic, 1e-4 * classic);
}

TEST(Hemicube, SideFaceDeltaFormFactorsApproachTheirDifferentialFormula) {
  // The hemicube lesson's side-face formula: a pixel of the face x = 1 at (1, y, z), z its height above the
  // element's plane, has z dA / (pi (y^2 + z^2 + 1)^2). The sides' rows run from the horizon upwards.
  const int res = 256, rows = hemicubeSideRows(res);
  const int row = 40, column = res / 2 - 30;
  for (HemicubeFace face : {HemicubeFace::PlusU, HemicubeFace::MinusV}) {
    const auto& side = deltaFormFactors(res, face);
    const double y = -1 + (column + 0.5) * 2.0 / res, z = (row + 0.5) / rows;
    const double classic =
        (2.0 / res) * (1.0 / rows) * z / (std::numbers::pi * std::pow(y * y + z * z + 1, 2));
    EXPECT_NEAR(side[row * res + column], classic, 1e-4 * classic) << static_cast<int>(face);
  }
}

TEST(Hemicube, FacesOfAClosedBoxAreFullAndSeeTheRightWalls) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 1, 1), 1);
  for (int res : {2, 7, 32, 65}) {
    const HemicubeFaces h = renderHemicube(mesh, 0, res);  // the floor
    for (const auto& face : h.faces) {
      for (int id : face.element) EXPECT_GE(id, 1) << res;  // every pixel sees a wall, never the floor itself
    }
    EXPECT_EQ(h.faces[0].element[(res / 2) * res + res / 2], 1);  // straight up: the ceiling
    EXPECT_NEAR(h.faces[0].depth[(res / 2) * res + res / 2], 1.0, 1e-6);
    std::vector<double> row(mesh.size(), 0.0);
    accumulateHemicubeRow(h, row.data());
    EXPECT_NEAR(std::accumulate(row.begin(), row.end(), 0.0), 1.0, 1e-12);
  }
}

TEST(Hemicube, ConvergesToThePointFormFactorOfTheCentroid) {
  // With one element per face the hemicube measures F(centroid -> face); the pixel-centre aliasing error of
  // an edge is O(1/res), so 512 brings it to a few 1e-3.
  const Mesh mesh = test::meshOf(test::closedBox(1, 2, 3), 1);
  const HemicubeFaces h = renderHemicube(mesh, 0, 512);
  std::vector<double> row(mesh.size(), 0.0);
  accumulateHemicubeRow(h, row.data());
  for (int j = 1; j < 6; ++j) {
    const double exact =
        pointToPolygonFormFactor(mesh.elements[0].centroid, mesh.elements[0].normal, mesh.polygon(j));
    EXPECT_NEAR(row[j], exact, 3e-3) << j;
  }
}

// Polygons are one-sided but opaque: a panel between floor and ceiling that turns its back to the floor
// hides the ceiling (the pixels show its back) instead of letting the floor see through it, as rays and the
// exact method do. Turned the other way it is seen like any element.
TEST(Hemicube, BackFacesBlockAndReceiveNothing) {
  for (const bool backToTheFloor : {true, false}) {
    Scene s = test::emptyScene();
    test::addQuad(s, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});  // floor, facing up
    test::addQuad(s, {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1});  // ceiling, facing down
    const Vec3 a(-2, -2, 0.5), b(3, -2, 0.5), c(3, 3, 0.5), d(-2, 3, 0.5);
    if (backToTheFloor)
      test::addQuad(s, a, b, c, d);
    else
      test::addQuad(s, a, d, c, b);
    const Mesh mesh = test::meshOf(s, 1);
    const HemicubeFaces h = renderHemicube(mesh, 0, 32);
    const int centre = h.faces[0].element[16 * 32 + 16];
    EXPECT_EQ(centre, backToTheFloor ? kHemicubeSeesBackFace : 2);
    EXPECT_NEAR(h.faces[0].depth[16 * 32 + 16], 0.5, 1e-6);  // a back face has a depth too
    std::vector<double> row(mesh.size(), 0.0);
    accumulateHemicubeRow(h, row.data());
    EXPECT_EQ(row[1], 0.0);  // the ceiling is hidden either way
    EXPECT_NEAR(row[2],
                backToTheFloor ? 0.0 : pointToPolygonFormFactor({0.5, 0.5, 0}, {0, 0, 1}, mesh.polygon(2)),
                2e-2);
  }
}

// An occluder modelled as two back-to-back polygons in one plane (occluded-plates.json): seen from either
// side the face towards the eye wins the depth test, in whichever order the two are drawn.
TEST(Hemicube, BackToBackPolygonsShowTheirFrontFace) {
  for (const bool frontFirst : {true, false}) {
    Scene s = test::emptyScene();
    test::addQuad(s, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});  // source, facing up
    const Vec3 a(0.25, 0.25, 0.5), b(0.75, 0.25, 0.5), c(0.75, 0.75, 0.5), d(0.25, 0.75, 0.5);
    if (frontFirst) test::addQuad(s, a, d, c, b);  // facing down, to the source
    test::addQuad(s, a, b, c, d);                  // facing up, away from the source
    if (!frontFirst) test::addQuad(s, a, d, c, b);
    const Mesh mesh = test::meshOf(s, 1);
    const int front = frontFirst ? 1 : 2, back = frontFirst ? 2 : 1;
    for (int resolution : {16, 64, 128}) {
      const HemicubeFaces h = renderHemicube(mesh, 0, resolution);
      for (const HemicubeFaceBuffer& face : h.faces)
        for (int id : face.element) EXPECT_NE(id, kHemicubeSeesBackFace) << resolution;
      std::vector<double> row(mesh.size(), 0.0);
      accumulateHemicubeRow(h, row.data());
      EXPECT_EQ(row[static_cast<std::size_t>(back)], 0.0);
      EXPECT_NEAR(row[static_cast<std::size_t>(front)],
                  pointToPolygonFormFactor({0.5, 0.5, 0}, {0, 0, 1}, mesh.polygon(front)), 2e-2)
          << resolution;
    }
  }
}

// Rows drawn one after another in one workspace, from the mesh's flat records, are the rows of hemicubes
// drawn one by one: nothing of the last eye's buffers is left in the next.
TEST(Hemicube, RowsFromOneWorkspaceAreTheOneByOneRows) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 3);
  const HemicubeMesh elements(mesh);
  HemicubeWorkspace workspace;
  std::vector<double> reused(mesh.size()), alone(mesh.size());
  for (int i : {0, 17, 5, 53, 0}) {
    hemicubeRow(elements, i, 24, workspace, reused.data());
    std::fill(alone.begin(), alone.end(), 0.0);
    accumulateHemicubeRow(renderHemicube(mesh, i, 24), alone.data());
    EXPECT_EQ(reused, alone) << i;
  }
}

// The records hold at most 8 corners (a convex patch kept whole has up to 8): more is refused by name.
TEST(Hemicube, AnElementOfMoreThanEightCornersIsRefusedByName) {
  Mesh mesh = test::meshOf(test::roomWithBlock(), 1);
  Element& e = mesh.elements[2];
  while (e.vertices.size() < 9) e.vertices.push_back(e.vertices[0]);
  try {
    const HemicubeMesh elements(mesh);
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("element 2 has 9 corners"), std::string::npos) << error.what();
  }
}

TEST(Nusselt, OutlineAreaConvergesToLambertQuadratically) {
  const Polygon square = {{-0.3, -0.2, 1}, {-0.3, 0.6, 1.4}, {0.7, 0.6, 1.4}, {0.7, -0.2, 1}};
  const Vec3 point = Vec3::Zero(), normal(0, 0, 1);
  const double exact = pointToPolygonFormFactor(point, normal, square);
  ASSERT_GT(exact, 0.05);
  double previous = 1;
  for (int segments : {4, 8, 16, 32}) {
    const NusseltProjection p = nusseltProject(point, normal, square, segments);
    const double error = std::abs(p.formFactor - exact);
    EXPECT_LT(error, 0.3 * previous + 1e-15);  // halving the segments' angle divides the error by ~4
    previous = error;
    EXPECT_EQ(p.diskOutline.size(), 4u * segments);
    for (const Vec2& q : p.diskOutline) EXPECT_LE(q.norm(), 1.0 + 1e-12);
    for (const Vec3& s : p.sphereOutline) EXPECT_NEAR(s.norm(), 1.0, 1e-12);
  }
  EXPECT_NEAR(nusseltFormFactor(point, normal, square.data(), 4, 256), exact, 1e-5 * exact);
}

TEST(Nusselt, ClipsAtTheHorizonLikeLambert) {
  // A wall standing on the point's tangent plane, half of it below: only the upper half projects.
  const Polygon wall = {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}};
  const Polygon facing = {wall[0], wall[3], wall[2], wall[1]};  // towards the point (-x)
  const Vec3 point = Vec3::Zero(), normal(0, 0, 1);
  const double exact = pointToPolygonFormFactor(point, normal, facing);
  EXPECT_GT(exact, 0);
  EXPECT_NEAR(nusseltProject(point, normal, facing, 512).formFactor, exact, 1e-5);
  EXPECT_EQ(nusseltProject(point, normal, wall, 16).formFactor, 0.0);  // its back faces the point
}

}  // namespace
}  // namespace rt
