// The elements as VTK cells: one polygon per element, a point per corner, the paint's colours; a recolour
// rewrites the colour array in place and leaves the cells alone (what lets the renderer keep its buffers).
#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <stdexcept>

#include "viz/element_polydata.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

Mesh gridRoom() {
  return vizt::openRoomMesh(6);
}

TEST(ElementPolyData, OneCellPerElementAndAPointPerCorner) {
  const Mesh mesh = gridRoom();
  SceneViewOptions options;
  SceneViewData data;
  data.B = mesh.emission + RgbField::Constant(static_cast<Eigen::Index>(mesh.size()), 3, 1.0);
  const ScenePaint paint = paintScene(mesh, data, options);
  const auto polyData = makeElementPolyData(mesh, paint);
  ASSERT_EQ(polyData->GetNumberOfCells(), static_cast<vtkIdType>(mesh.size()));
  EXPECT_EQ(polyData->GetNumberOfPoints(), static_cast<vtkIdType>(paint.colours.size()));
  auto* ids = vtkIntArray::SafeDownCast(polyData->GetCellData()->GetArray("element"));
  ASSERT_NE(ids, nullptr);
  for (std::size_t e = 0; e < mesh.size(); e += 7) {
    EXPECT_EQ(ids->GetValue(static_cast<vtkIdType>(e)), static_cast<int>(e));
    const vtkIdType* points = nullptr;
    vtkIdType count = 0;
    polyData->GetPolys()->GetCellAtId(static_cast<vtkIdType>(e), count, points);
    ASSERT_EQ(count, static_cast<vtkIdType>(mesh.elements[e].vertices.size()));
    for (vtkIdType k = 0; k < count; ++k) {
      double p[3];
      polyData->GetPoint(points[k], p);
      const Vec3& expected = mesh.vertices[mesh.elements[e].vertices[static_cast<std::size_t>(k)]];
      EXPECT_NEAR((Vec3(p[0], p[1], p[2]) - expected).norm(), 0.0, 1e-5);
      EXPECT_EQ(points[k], paint.firstCorner[e] + k);
    }
  }
}

TEST(ElementPolyData, RecolouringRewritesTheColoursAndKeepsTheCells) {
  const Mesh mesh = gridRoom();
  SceneViewOptions options;
  SceneViewData data;
  data.B = RgbField::Constant(static_cast<Eigen::Index>(mesh.size()), 3, 0.2);
  const auto polyData = makeElementPolyData(mesh, paintScene(mesh, data, options));
  vtkCellArray* cells = polyData->GetPolys();
  const vtkMTimeType cellsTime = cells->GetMTime();
  auto* colours = vtkUnsignedCharArray::SafeDownCast(polyData->GetPointData()->GetScalars());
  ASSERT_NE(colours, nullptr);
  const vtkMTimeType coloursTime = colours->GetMTime();

  data.B.col(0).setConstant(5.0);  // a red room, the rest as before
  options.image.smooth = true;
  const ScenePaint repainted = paintScene(mesh, data, options);
  updateElementColours(*polyData, repainted);
  EXPECT_EQ(polyData->GetPolys(), cells);
  EXPECT_EQ(cells->GetMTime(), cellsTime);
  EXPECT_GT(colours->GetMTime(), coloursTime);
  for (std::size_t k = 0; k < repainted.colours.size(); k += 11)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(colours->GetTypedComponent(static_cast<vtkIdType>(k), c), repainted.colours[k][c]);

  updateElementColours(*polyData, ScenePaint{});  // nothing to show: grey
  EXPECT_EQ(colours->GetTypedComponent(0, 0), 200);
  ScenePaint wrong = repainted;
  wrong.colours.pop_back();
  EXPECT_THROW(updateElementColours(*polyData, wrong), std::invalid_argument);
}

}  // namespace
}  // namespace rt::viz
