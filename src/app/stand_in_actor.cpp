#include "app/stand_in_actor.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <chrono>

namespace rt::app {

StandInActor::StandInActor(vtkRenderer& renderer) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToDirectScalars();
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  actor_->PickableOff();
  actor_->VisibilityOff();
  renderer.AddActor(actor_);
}

StandInActor::~StandInActor() = default;

void StandInActor::rebuild(const Mesh* mesh, const viz::ScenePaint& painted) {
  mesh_ = nullptr;
  data_ = nullptr;
  actor_->GetMapper()->SetInputDataObject(nullptr);
  actor_->VisibilityOff();
  if (!mesh || !viz::wantsStandIn(*mesh)) return;
  // On the calling thread, with the mesh's cells: some 135 ms at a million elements, against about 320 ms
  // for the cells themselves, so not worth a thread that would have to outlive a mesh being replaced.
  const auto start = std::chrono::steady_clock::now();
  mesh_ = std::make_unique<viz::StandInMesh>(*mesh);
  data_ = mesh_->makePolyData(painted);
  actor_->GetMapper()->SetInputDataObject(data_);
  buildMilliseconds_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void StandInActor::recolour(const viz::ScenePaint& painted) {
  if (mesh_) mesh_->recolour(*data_, painted);
}

void StandInActor::show(vtkActor& full) {
  if (!data_) return;
  // The mesh's look (lighting of the material view, culling), but neither its edges (the stand-in's
  // triangles are not the elements) nor flat shading (its colours are means over clusters, best blended).
  vtkProperty* property = actor_->GetProperty();
  property->DeepCopy(full.GetProperty());
  property->EdgeVisibilityOff();
  property->SetInterpolationToGouraud();
  actor_->VisibilityOn();
  full.VisibilityOff();
}

void StandInActor::hide(vtkActor& full, bool fullVisible) {
  actor_->VisibilityOff();
  full.SetVisibility(fullVisible);
}

vtkPolyData* StandInActor::polyData() const {
  return data_;
}

}  // namespace rt::app
