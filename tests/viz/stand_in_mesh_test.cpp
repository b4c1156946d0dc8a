// The coarse stand-in of a large mesh (drawn while the camera moves): about the asked number of triangles,
// on the mesh's surfaces, wound as the elements are, with the colours of the corners it replaces and never a
// colour from a surface facing another way; a recolouring rewrites its colours and leaves its triangles.
// The app's side (which of the two is drawn when) is tests/app/stand_in_view_test.cpp.
#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "core/io/scene_loader.h"
#include "viz/stand_in_mesh.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

// The open unit room, each wall cut n x n (12 n^2 triangles).
Mesh gridRoom(int n) {
  MeshOptions o;
  o.mode = MeshOptions::Mode::Count;
  o.count = n;
  return buildMesh(vizt::openRoom(), o);
}

// Each element coloured by the way it faces (the red and green walls stay red and green, the floor blue).
ScenePaint paintByFacing(const Mesh& mesh) {
  ScenePaint paint;
  for (const Element& element : mesh.elements) {
    paint.firstCorner.push_back(static_cast<int>(paint.colours.size()));
    const Vec3& n = element.normal;
    const Rgb8 colour = n.x() > 0.5    ? Rgb8{220, 30, 20}
                        : n.x() < -0.5 ? Rgb8{30, 200, 40}
                        : n.y() > 0.5  ? Rgb8{40, 60, 210}
                                       : Rgb8{180, 180, 180};
    paint.colours.insert(paint.colours.end(), element.vertices.size(), colour);
  }
  paint.firstCorner.push_back(static_cast<int>(paint.colours.size()));
  return paint;
}

Vec3 pointOf(vtkPolyData& data, vtkIdType id) {
  double p[3];
  data.GetPoint(id, p);
  return {p[0], p[1], p[2]};
}

}  // namespace

TEST(StandInMesh, OnlyMeshesAboveTheThresholdGetOne) {
  EXPECT_FALSE(wantsStandIn(gridRoom(10)));
  const Mesh large = gridRoom(130);  // 6 walls' worth of 130 x 130 quads: 202,800 triangles
  EXPECT_EQ(triangleCount(large), 12u * 130 * 130);
  EXPECT_TRUE(wantsStandIn(large));
}

TEST(StandInMesh, HasAboutTheTargetTrianglesOnTheSurfacesWoundAsTheElements) {
  const Mesh mesh = gridRoom(60);
  const StandInMesh standIn(mesh, 4000);
  EXPECT_GT(standIn.triangleCount(), 2000u);
  EXPECT_LT(standIn.triangleCount(), 6000u);
  EXPECT_EQ(standIn.cornerCount(), 4 * mesh.size());
  const auto data = standIn.makePolyData(paintByFacing(mesh));
  ASSERT_EQ(data->GetNumberOfPolys(), static_cast<vtkIdType>(standIn.triangleCount()));
  // Every point on a wall of the unit room (the light hangs 1 mm under the ceiling: a shared bin may sit
  // between the two).
  for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p) {
    const Vec3 x = pointOf(*data, p);
    const double toWall = std::min({x.x(), 1 - x.x(), x.y(), 1 - x.y(), x.z()});
    EXPECT_LT(toWall, 2e-3) << "point " << p << " at " << x.transpose();
  }
  // Faces towards the inside of the room, as the elements do (back-face culling depends on it).
  const Vec3 inside(0.5, 0.5, 0.5);
  int outward = 0, counted = 0;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (vtkIdType t = 0; t < data->GetNumberOfPolys(); ++t) {
    data->GetPolys()->GetCellAtId(t, count, ids);
    const Vec3 a = pointOf(*data, ids[0]), b = pointOf(*data, ids[1]), c = pointOf(*data, ids[2]);
    const Vec3 normal = (b - a).cross(c - a);
    if (normal.norm() < 1e-9) continue;  // collapsed in a corner bin
    ++counted;
    if (normal.dot(inside - (a + b + c) / 3) < 0) ++outward;
  }
  EXPECT_GT(counted, 1000);
  EXPECT_EQ(outward, 0);
}

TEST(StandInMesh, KeepsEachSurfacesColourAndFollowsARecolouringInPlace) {
  const Mesh mesh = gridRoom(60);
  const StandInMesh standIn(mesh, 4000);
  const ScenePaint paint = paintByFacing(mesh);
  const auto data = standIn.makePolyData(paint);
  auto* colours = vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetScalars());
  ASSERT_NE(colours, nullptr);
  // A triangle of the red wall (facing +x) has three red points: no colour crosses a corner of the room.
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  int red = 0;
  for (vtkIdType t = 0; t < data->GetNumberOfPolys(); ++t) {
    data->GetPolys()->GetCellAtId(t, count, ids);
    const Vec3 a = pointOf(*data, ids[0]), b = pointOf(*data, ids[1]), c = pointOf(*data, ids[2]);
    const Vec3 normal = (b - a).cross(c - a).normalized();
    if (!(normal.x() > 0.99)) continue;
    ++red;
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(colours->GetTypedComponent(ids[k], 0), 220);
      EXPECT_EQ(colours->GetTypedComponent(ids[k], 1), 30);
      EXPECT_EQ(colours->GetTypedComponent(ids[k], 2), 20);
    }
  }
  EXPECT_GT(red, 100);

  // A new colouring: the same triangles, the colours the mean of the new corners.
  const vtkMTimeType cellsTime = data->GetPolys()->GetMTime();
  ScenePaint brighter = paint;
  for (Rgb8& colour : brighter.colours) colour = Rgb8{250, 240, 10};
  standIn.recolour(*data, brighter);
  EXPECT_EQ(data->GetPolys()->GetMTime(), cellsTime);
  for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p) {
    ASSERT_EQ(colours->GetTypedComponent(p, 0), 250);
    ASSERT_EQ(colours->GetTypedComponent(p, 2), 10);
  }
  standIn.recolour(*data, ScenePaint{});  // no paint: grey, as the mesh's cells
  EXPECT_EQ(colours->GetTypedComponent(0, 0), 200);
  ScenePaint wrong = paint;
  wrong.colours.pop_back();
  EXPECT_THROW(standIn.recolour(*data, wrong), std::invalid_argument);
}

// The cost at a scene of the reader's (RT_STAND_IN_SCENE, e.g. the million-element museum of
// scenes/tools/bench_app.sh): build and recolour. Disabled: the scene is generated.
TEST(StandInMesh, DISABLED_CostOnALargeScene) {
  const char* path = std::getenv("RT_STAND_IN_SCENE");
  ASSERT_NE(path, nullptr) << "set RT_STAND_IN_SCENE to an OBJ file";
  const Mesh mesh = buildMesh(loadScene(path));
  const ScenePaint paint = paintByFacing(mesh);
  using Clock = std::chrono::steady_clock;
  auto milliseconds = [](Clock::time_point since) {
    return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
  };
  const auto start = Clock::now();
  const StandInMesh standIn(mesh);
  const double build = milliseconds(start);
  const auto polyStart = Clock::now();
  const auto data = standIn.makePolyData(paint);
  const double poly = milliseconds(polyStart);
  const auto recolourStart = Clock::now();
  standIn.recolour(*data, paint);
  const double recolour = milliseconds(recolourStart);
  std::printf(
      "%zu elements, %zu triangles -> %zu clusters, %zu triangles (bin %.3f): build %.0f ms, "
      "polydata %.1f ms, recolour %.1f ms\n",
      mesh.size(), triangleCount(mesh), standIn.clusterCount(), standIn.triangleCount(), standIn.binSize(),
      build, poly, recolour);
}

}  // namespace rt::viz
