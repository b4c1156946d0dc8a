#include "viz/element_polydata.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace rt::viz {
namespace {

constexpr std::uint8_t kUnpainted = 200;

// Offsets (n + 1) and connectivity (0, 1, 2, ...: every corner is a point of its own) of the polygons, in the
// narrowest integer type that holds them: at a million quads, 32-bit ids halve the cell array's 40 MB.
template <typename IdArray>
void setPolygons(vtkCellArray& polygons, const Mesh& mesh, vtkIdType corners) {
  using Id = typename IdArray::ValueType;
  auto offsets = vtkSmartPointer<IdArray>::New();
  offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.size()) + 1);
  Id* offset = offsets->GetPointer(0);
  offset[0] = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e)
    offset[e + 1] = offset[e] + static_cast<Id>(mesh.elements[e].vertices.size());
  auto connectivity = vtkSmartPointer<IdArray>::New();
  connectivity->SetNumberOfValues(corners);
  Id* ids = connectivity->GetPointer(0);
  std::iota(ids, ids + corners, Id{0});
  polygons.SetData(offsets, connectivity);
}

}  // namespace

vtkSmartPointer<vtkPolyData> makeElementPolyData(const Mesh& mesh, const ScenePaint& paint) {
  vtkIdType corners = 0;
  for (const Element& element : mesh.elements) corners += static_cast<vtkIdType>(element.vertices.size());

  auto coordinates = vtkSmartPointer<vtkFloatArray>::New();
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(corners);
  float* xyz = coordinates->GetPointer(0);
  for (const Element& element : mesh.elements)
    for (int v : element.vertices) {
      const Vec3& p = mesh.vertices[static_cast<std::size_t>(v)];
      *xyz++ = static_cast<float>(p.x());
      *xyz++ = static_cast<float>(p.y());
      *xyz++ = static_cast<float>(p.z());
    }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coordinates);

  auto polygons = vtkSmartPointer<vtkCellArray>::New();
  if (corners < std::numeric_limits<std::int32_t>::max())
    setPolygons<vtkTypeInt32Array>(*polygons, mesh, corners);
  else
    setPolygons<vtkTypeInt64Array>(*polygons, mesh, corners);

  auto ids = vtkSmartPointer<vtkIntArray>::New();
  ids->SetName("element");
  ids->SetNumberOfValues(static_cast<vtkIdType>(mesh.size()));
  std::iota(ids->GetPointer(0), ids->GetPointer(0) + mesh.size(), 0);

  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetName("colour");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(corners);

  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polygons);
  data->GetPointData()->SetScalars(colours);
  data->GetCellData()->AddArray(ids);
  updateElementColours(*data, paint);
  return data;
}

void updateElementColours(vtkPolyData& data, const ScenePaint& paint) {
  auto* colours = vtkUnsignedCharArray::SafeDownCast(data.GetPointData()->GetArray("colour"));
  if (!colours) throw std::invalid_argument("the polydata has no colour array");
  const std::size_t corners = static_cast<std::size_t>(colours->GetNumberOfTuples());
  const std::size_t elements = static_cast<std::size_t>(data.GetNumberOfPolys());
  std::uint8_t* bytes = colours->GetPointer(0);
  if (paint.firstCorner.size() == elements + 1) {
    if (paint.colours.size() != corners || static_cast<std::size_t>(paint.firstCorner.back()) != corners)
      throw std::invalid_argument("the paint has " + std::to_string(paint.colours.size()) + " corners for " +
                                  std::to_string(corners));
    static_assert(sizeof(Rgb8) == 3, "Rgb8 is three packed bytes");
    std::memcpy(bytes, paint.colours.data(), 3 * corners);
  } else {
    std::fill(bytes, bytes + 3 * corners, kUnpainted);
  }
  colours->Modified();
}

}  // namespace rt::viz
