// Material views outline the lights: the outline runs around each light, not along the mesh lines inside it.
#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>

#include "core/io/scene_loader.h"
#include "support/test_paths.h"
#include "viz/vtk_views.h"

namespace rt::viz {
namespace {

vtkIdType outlineSegments(const Mesh& mesh) {
  const auto actor = makeEmitterOutlineActor(mesh, 2.0);
  if (!actor) return -1;
  auto* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
  return data ? data->GetLines()->GetNumberOfCells() : -1;
}

TEST(EmitterOutline, RunsAroundTheLightAndNotAlongItsInnerMeshLines) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  const Mesh whole = buildMesh(scene);
  EXPECT_EQ(outlineSegments(whole), 4);  // the light is one quadrilateral
  MeshOptions three;
  three.mode = MeshOptions::Mode::Count;
  three.count = 3;
  const Mesh split = buildMesh(scene, three);
  EXPECT_EQ(outlineSegments(split), 12);  // 3 x 3 elements: 3 segments along each side, none inside
}

TEST(EmitterOutline, NothingToOutlineWithoutALight) {
  Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  Mesh mesh = buildMesh(scene);
  mesh.emission.setZero();
  EXPECT_EQ(makeEmitterOutlineActor(mesh, 2.0), nullptr);
}

}  // namespace
}  // namespace rt::viz
