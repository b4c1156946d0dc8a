#include "viz/faded_scene.h"

#include <vtkActor.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "viz/scene_view.h"
#include "viz/vtk_render.h"
#include "viz/vtk_views.h"

namespace rt::viz {

vtkSmartPointer<vtkRenderer> addFadedScene(const Mesh& mesh, const Camera& camera, const FigureSize& size,
                                           vtkRenderWindow* window, const double* viewport) {
  SceneViewOptions sceneOptions;
  sceneOptions.colouring = SceneColouring::Reflectance;
  sceneOptions.image.showEdges = true;
  sceneOptions.dpi = size.dpi;
  const ScenePaint paint = paintScene(mesh, {}, sceneOptions);
  const double full[4] = {0, 0, 1, 1};
  vtkSmartPointer<vtkRenderer> renderer =
      makeSceneRenderer(mesh, camera, paint, sceneOptions, size.height, viewport ? viewport : full);
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor()) actor->GetProperty()->SetOpacity(0.3);
  window->AddRenderer(renderer);
  enableDepthPeeling(window, renderer);  // the faint room around the rays
  return renderer;
}

}  // namespace rt::viz
