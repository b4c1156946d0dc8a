#include "viz/vtk_geometry.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkGlyph3D.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTriangleFilter.h>

namespace rt::viz {
namespace {

vtkSmartPointer<vtkPoints> pointsOf(const std::vector<Vec3>& points) {
  auto out = vtkSmartPointer<vtkPoints>::New();
  out->SetDataTypeToDouble();
  for (const Vec3& p : points) out->InsertNextPoint(p.x(), p.y(), p.z());
  return out;
}

vtkSmartPointer<vtkActor> actorOf(vtkPolyData* data, const Colour& colour, double opacity, bool lighting) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetOpacity(opacity);
  actor->GetProperty()->SetLighting(lighting);
  return actor;
}

}  // namespace

vtkSmartPointer<vtkActor> polygonActor(const std::vector<Vec3>& points, const Colour& colour, double opacity,
                                       bool lighting) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->InsertNextCell(static_cast<vtkIdType>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) cells->InsertCellPoint(static_cast<vtkIdType>(k));
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pointsOf(points));
  data->SetPolys(cells);
  auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
  triangles->SetInputData(data);
  triangles->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(triangles->GetOutput());
  return actorOf(out, colour, opacity, lighting);
}

vtkSmartPointer<vtkActor> trianglesActor(const std::vector<Vec3>& points, const Colour& colour,
                                         double opacity) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (std::size_t k = 0; k + 2 < points.size(); k += 3) {
    cells->InsertNextCell(3);
    for (std::size_t j = 0; j < 3; ++j) cells->InsertCellPoint(static_cast<vtkIdType>(k + j));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pointsOf(points));
  data->SetPolys(cells);
  return actorOf(data, colour, opacity, false);
}

vtkSmartPointer<vtkActor> linesActor(const std::vector<Vec3>& points, const Colour& colour, double width) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (std::size_t k = 0; k + 1 < points.size(); k += 2) {
    cells->InsertNextCell(2);
    cells->InsertCellPoint(static_cast<vtkIdType>(k));
    cells->InsertCellPoint(static_cast<vtkIdType>(k + 1));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pointsOf(points));
  data->SetLines(cells);
  auto actor = actorOf(data, colour, 1.0, false);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  return actor;
}

vtkSmartPointer<vtkActor> loopActor(const std::vector<Vec3>& points, const Colour& colour, double width) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->InsertNextCell(static_cast<vtkIdType>(points.size() + 1));
  for (std::size_t k = 0; k < points.size(); ++k) cells->InsertCellPoint(static_cast<vtkIdType>(k));
  cells->InsertCellPoint(0);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pointsOf(points));
  data->SetLines(cells);
  auto actor = actorOf(data, colour, 1.0, false);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  return actor;
}

vtkSmartPointer<vtkActor> pointsActor(const std::vector<Vec3>& points, const Colour& colour, double radius) {
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pointsOf(points));
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  auto glyphs = vtkSmartPointer<vtkGlyph3D>::New();
  glyphs->SetInputData(data);
  glyphs->SetSourceConnection(sphere->GetOutputPort());
  glyphs->ScalingOff();
  glyphs->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(glyphs->GetOutput());
  return actorOf(out, colour, 1.0, true);
}

vtkSmartPointer<vtkActor> hemisphereActor(const Vec3& origin, const Vec3& u, const Vec3& v,
                                          const Vec3& normal, double radius, const Colour& colour,
                                          double opacity, bool wireframe) {
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(wireframe ? 24 : 96);
  sphere->SetPhiResolution(wireframe ? 8 : 48);
  sphere->SetStartPhi(0);
  sphere->SetEndPhi(90);  // phi from +z: the upper half
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 3; ++r) {
    matrix->SetElement(r, 0, u[r]);
    matrix->SetElement(r, 1, v[r]);
    matrix->SetElement(r, 2, normal[r]);
    matrix->SetElement(r, 3, origin[r]);
  }
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->SetMatrix(matrix);
  auto filter = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  filter->SetInputConnection(sphere->GetOutputPort());
  filter->SetTransform(transform);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(filter->GetOutput());
  auto actor = actorOf(out, colour, opacity, !wireframe);
  if (wireframe) {
    actor->GetProperty()->SetRepresentationToWireframe();
    actor->GetProperty()->SetLineWidth(1.0f);
  }
  return actor;
}

void frameFromDirection(vtkRenderer* renderer, const Vec3& direction, const Vec3& up, double zoom) {
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const Vec3 centre(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                    0.5 * (bounds[4] + bounds[5]));
  vtkCamera* camera = renderer->GetActiveCamera();
  const Vec3 eye = centre + direction.normalized();
  camera->SetFocalPoint(centre.x(), centre.y(), centre.z());
  camera->SetPosition(eye.x(), eye.y(), eye.z());
  camera->SetViewUp(up.x(), up.y(), up.z());
  camera->SetViewAngle(30);
  renderer->ResetCamera();
  camera->Zoom(zoom);
  renderer->ResetCameraClippingRange();
}

}  // namespace rt::viz
