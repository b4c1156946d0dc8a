// The actor of a large mesh's coarse stand-in in the 3D view (viz/stand_in_mesh.h): built with the mesh's
// cells, recoloured with them, and shown in place of the mesh's actor while the camera moves. It is never
// picked: picks, exports and the still frame always see the full mesh.
#pragma once

#include <vtkSmartPointer.h>

#include <memory>

#include "viz/stand_in_mesh.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace rt::app {

class StandInActor {
 public:
  // Adds the (hidden) actor to `renderer`.
  explicit StandInActor(vtkRenderer& renderer);
  ~StandInActor();

  // A new mesh: its stand-in when it is large enough to need one (viz::wantsStandIn), else none.
  void rebuild(const Mesh* mesh, const viz::ScenePaint& painted);
  // New colours of the same mesh: the stand-in's follow, its triangles stay.
  void recolour(const viz::ScenePaint& painted);
  bool available() const { return data_ != nullptr; }
  // Drawn instead of `full` (taking its look), or `full` again.
  void show(vtkActor& full);
  void hide(vtkActor& full, bool fullVisible);

  vtkPolyData* polyData() const;
  double buildMilliseconds() const { return buildMilliseconds_; }

 private:
  vtkSmartPointer<vtkActor> actor_;
  std::unique_ptr<viz::StandInMesh> mesh_;
  vtkSmartPointer<vtkPolyData> data_;
  double buildMilliseconds_ = 0.0;
};

}  // namespace rt::app
