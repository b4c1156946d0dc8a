#include "app/radiosity_polydata.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

namespace rt::app {
namespace {

double srgb(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace

double automaticExposure(const Mesh& mesh, const RgbField& B) {
  double brightest = 0;
  for (Eigen::Index i = 0; i < B.rows(); ++i) {
    const bool emits = i < mesh.emission.rows() && mesh.emission.row(i).maxCoeff() > 0;
    if (!emits) brightest = std::max(brightest, B.row(i).maxCoeff());
  }
  if (brightest <= 0) brightest = B.size() > 0 ? B.maxCoeff() : 1.0;
  return brightest > 0 ? 1.0 / brightest : 1.0;
}

Eigen::Matrix<unsigned char, Eigen::Dynamic, 3> displayColours(const Mesh& mesh, const RgbField& B,
                                                               const DisplayOptions& options) {
  const double exposure = options.exposure > 0 ? options.exposure : automaticExposure(mesh, B);
  Eigen::Matrix<unsigned char, Eigen::Dynamic, 3> colours(B.rows(), 3);
  for (Eigen::Index i = 0; i < B.rows(); ++i) {
    for (int c = 0; c < 3; ++c) {
      double v = std::max(0.0, B(i, c) * exposure);
      v = options.reinhard ? v / (1.0 + v) : std::min(v, 1.0);
      if (options.gamma) v = srgb(v);
      colours(i, c) = static_cast<unsigned char>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    }
  }
  return colours;
}

vtkSmartPointer<vtkPolyData> makeRadiosityPolyData(const Mesh& mesh, const RgbField& B,
                                                   const DisplayOptions& options) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    points->SetPoint(static_cast<vtkIdType>(v), mesh.vertices[v].data());

  auto polygons = vtkSmartPointer<vtkCellArray>::New();
  for (const Element& e : mesh.elements) {
    std::vector<vtkIdType> ids(e.vertices.begin(), e.vertices.end());
    polygons->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }

  const bool haveB = B.rows() == static_cast<Eigen::Index>(mesh.size());
  const auto colours = haveB ? displayColours(mesh, B, options)
                             : Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>::Constant(
                                   static_cast<Eigen::Index>(mesh.size()), 3, 128);
  auto colourArray = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colourArray->SetName("Colors");
  colourArray->SetNumberOfComponents(3);
  colourArray->SetNumberOfTuples(static_cast<vtkIdType>(mesh.size()));
  auto idArray = vtkSmartPointer<vtkIntArray>::New();
  idArray->SetName("ElementId");
  idArray->SetNumberOfTuples(static_cast<vtkIdType>(mesh.size()));
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    const auto cell = static_cast<vtkIdType>(i);
    for (int c = 0; c < 3; ++c) colourArray->SetTypedComponent(cell, c, colours(row, c));
    idArray->SetValue(cell, static_cast<int>(i));
  }

  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(polygons);
  polyData->GetCellData()->SetScalars(colourArray);
  polyData->GetCellData()->AddArray(idArray);
  return polyData;
}

}  // namespace rt::app
