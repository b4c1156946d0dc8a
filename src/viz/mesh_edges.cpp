#include "viz/mesh_edges.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTypeInt32Array.h>

#include <algorithm>
#include <chrono>

namespace rt::viz {

MeshEdgeTable meshEdgeTable(const Mesh& mesh) {
  MeshEdgeTable table;
  table.firstCorner.assign(mesh.size() + 1, 0);
  for (std::size_t e = 0; e < mesh.size(); ++e)
    table.firstCorner[e + 1] = table.firstCorner[e] + static_cast<int>(mesh.elements[e].vertices.size());
  const std::size_t corners = static_cast<std::size_t>(table.firstCorner.back());
  table.cornerEdge.assign(corners, -1);
  // The corners bucketed by the lower vertex of their edge: an edge is found again among the few edges of
  // that vertex, in time linear in the corners (a map over a million elements' edges takes seconds).
  std::vector<int> bucketStart(mesh.vertices.size() + 1, 0);
  auto ends = [&](std::size_t e, std::size_t k) {
    const auto& vs = mesh.elements[e].vertices;
    const int a = vs[k], b = vs[(k + 1) % vs.size()];
    return std::array<int, 2>{std::min(a, b), std::max(a, b)};
  };
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (std::size_t k = 0; k < mesh.elements[e].vertices.size(); ++k)
      ++bucketStart[static_cast<std::size_t>(ends(e, k)[0]) + 1];
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) bucketStart[v + 1] += bucketStart[v];
  std::vector<int> fill(bucketStart.begin(), bucketStart.end() - 1);
  std::vector<int> bucket(corners);  // corner indices
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (std::size_t k = 0; k < mesh.elements[e].vertices.size(); ++k)
      bucket[static_cast<std::size_t>(fill[static_cast<std::size_t>(ends(e, k)[0])]++)] =
          table.firstCorner[e] + static_cast<int>(k);
  std::vector<int> owner(corners);  // the element of each corner
  for (std::size_t e = 0; e < mesh.size(); ++e)
    std::fill(owner.begin() + table.firstCorner[e], owner.begin() + table.firstCorner[e + 1],
              static_cast<int>(e));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int i = bucketStart[v]; i < bucketStart[v + 1]; ++i) {
      const int corner = bucket[static_cast<std::size_t>(i)];
      const int e = owner[static_cast<std::size_t>(corner)];
      const auto edge =
          ends(static_cast<std::size_t>(e),
               static_cast<std::size_t>(corner - table.firstCorner[static_cast<std::size_t>(e)]));
      int found = -1;
      for (int j = bucketStart[v]; j < i && found < 0; ++j) {
        const int earlier = table.cornerEdge[static_cast<std::size_t>(bucket[static_cast<std::size_t>(j)])];
        if (table.edges[static_cast<std::size_t>(earlier)] == edge) found = earlier;
      }
      if (found < 0) {
        found = static_cast<int>(table.edges.size());
        table.edges.push_back(edge);
      }
      table.cornerEdge[static_cast<std::size_t>(corner)] = found;
    }
  return table;
}

vtkSmartPointer<MeshEdgeLines> MeshEdgeLines::make(const Mesh& mesh, const Colour& colour, double lineWidth) {
  vtkSmartPointer<MeshEdgeLines> lines = vtkSmartPointer<MeshEdgeLines>::Take(new MeshEdgeLines);
  lines->table_ = meshEdgeTable(mesh);
  lines->planes_.resize(mesh.size());
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& element = mesh.elements[e];
    lines->planes_[e] = {static_cast<float>(element.normal.x()), static_cast<float>(element.normal.y()),
                         static_cast<float>(element.normal.z()),
                         static_cast<float>(element.normal.dot(element.centroid))};
  }
  lines->drawn_.assign(lines->table_.edges.size(), 0);

  // Each vertex lifted a hair off the surfaces along the mean normal of its elements, towards the side they
  // face, so that the lines win the depth test against the faces they lie on (the coincident-topology offset
  // below helps where the normals cancel).
  std::vector<Vec3> lift(mesh.vertices.size(), Vec3::Zero());
  for (const Element& element : mesh.elements)
    for (int v : element.vertices) lift[static_cast<std::size_t>(v)] += element.normal;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  if (!mesh.vertices.empty()) lo = hi = mesh.vertices.front();
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double height = 1e-3 * (hi - lo).norm();
  auto coordinates = vtkSmartPointer<vtkFloatArray>::New();
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertices.size()));
  float* xyz = coordinates->GetPointer(0);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const double length = lift[v].norm();
    const Vec3 p = mesh.vertices[v] + (length > 1e-9 ? height / length : 0.0) * lift[v];
    *xyz++ = static_cast<float>(p.x());
    *xyz++ = static_cast<float>(p.y());
    *xyz++ = static_cast<float>(p.z());
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coordinates);
  lines->data_ = vtkSmartPointer<vtkPolyData>::New();
  lines->data_->SetPoints(points);
  lines->writeLines();  // none until the first choice

  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(lines->data_);
  mapper->ScalarVisibilityOff();
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-2, -4);
  lines->actor_ = vtkSmartPointer<vtkActor>::New();
  lines->actor_->SetMapper(mapper);
  lines->actor_->PickableOff();
  vtkProperty* property = lines->actor_->GetProperty();
  property->SetColor(colour[0], colour[1], colour[2]);
  property->LightingOff();
  property->SetLineWidth(static_cast<float>(lineWidth));
  return lines;
}

vtkActor* MeshEdgeLines::actor() const {
  return actor_;
}

vtkPolyData* MeshEdgeLines::polyData() const {
  return data_;
}

void MeshEdgeLines::addTo(vtkRenderer& renderer) {
  renderer.AddActor(actor_);
  observer_ = renderer.AddObserver(vtkCommand::StartEvent, this);
}

void MeshEdgeLines::removeFrom(vtkRenderer& renderer) {
  renderer.RemoveActor(actor_);
  renderer.RemoveObserver(observer_);
  observer_ = 0;
}

void MeshEdgeLines::Execute(vtkObject* caller, unsigned long, void*) {
  auto* renderer = vtkRenderer::SafeDownCast(caller);
  if (renderer && actor_->GetVisibility()) follow(*renderer->GetActiveCamera());
}

bool MeshEdgeLines::follow(vtkCamera& camera) {
  const auto start = std::chrono::steady_clock::now();
  // A perspective camera sees the front of an element when it stands in front of the element's plane; a
  // parallel one when it looks against the normal.
  const bool parallel = camera.GetParallelProjection() != 0;
  double eye[3], focal[3];
  camera.GetPosition(eye);
  camera.GetFocalPoint(focal);
  const double toward[3] = {eye[0] - focal[0], eye[1] - focal[1], eye[2] - focal[2]};
  bool changed = !chosen_;
  facing_.resize(planes_.size());
  for (std::size_t e = 0; e < planes_.size(); ++e) {
    const auto& p = planes_[e];
    const bool faces = parallel ? p[0] * toward[0] + p[1] * toward[1] + p[2] * toward[2] > 0
                                : p[0] * eye[0] + p[1] * eye[1] + p[2] * eye[2] > p[3];
    if (static_cast<bool>(facing_[e]) != faces) {
      facing_[e] = faces;
      changed = true;
    }
  }
  chosen_ = true;
  if (changed) {
    std::fill(drawn_.begin(), drawn_.end(), std::uint8_t{0});
    for (std::size_t e = 0; e < planes_.size(); ++e)
      if (facing_[e])
        for (int c = table_.firstCorner[e]; c < table_.firstCorner[e + 1]; ++c)
          drawn_[static_cast<std::size_t>(table_.cornerEdge[static_cast<std::size_t>(c)])] = 1;
    writeLines();
  }
  lastChoiceMilliseconds_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return changed;
}

void MeshEdgeLines::writeLines() {
  shown_ = static_cast<std::size_t>(std::count(drawn_.begin(), drawn_.end(), std::uint8_t{1}));
  auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
  offsets->SetNumberOfValues(static_cast<vtkIdType>(shown_ + 1));
  auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(2 * shown_));
  std::int32_t* offset = offsets->GetPointer(0);
  std::int32_t* ids = connectivity->GetPointer(0);
  *offset = 0;
  for (std::size_t edge = 0; edge < drawn_.size(); ++edge) {
    if (!drawn_[edge]) continue;
    offset[1] = offset[0] + 2;
    ++offset;
    *ids++ = table_.edges[edge][0];
    *ids++ = table_.edges[edge][1];
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  data_->SetLines(cells);
}

}  // namespace rt::viz
