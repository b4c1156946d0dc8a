// VTK-facing builders for hosts that own a render window (the Qt app's vtkGenericOpenGLRenderWindow): the
// same pipelines the figure functions render offscreen. Includes VTK; the rest of viz's public headers do
// not.
#pragma once

#include <vtkSmartPointer.h>

#include "viz/drawing.h"
#include "viz/element_polydata.h"
#include "viz/scene_view.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindow;

namespace rt::viz {

// The scene renderer: elements (no lighting: the colour is the displayed radiosity), optional mesh edges,
// highlight, caption, camera. `viewport` is xmin, ymin, xmax, ymax in normalised window coordinates.
vtkSmartPointer<vtkRenderer> makeSceneRenderer(const Mesh& mesh, const Camera& camera,
                                               const ScenePaint& paint, const SceneViewOptions& options,
                                               int windowHeight, const double viewport[4]);

// The outline of the emitting elements (the edges no two of them share), lifted a hair off the surface, for
// material views: a light reflects about as much as the ceiling around it and would not show otherwise. Null
// when nothing emits.
vtkSmartPointer<vtkActor> makeEmitterOutlineActor(const Mesh& mesh, double lineWidth);

// Adds the full scene view (scene renderer, and a colour-bar renderer on the right for scalar views) to a
// window.
void addSceneView(vtkRenderWindow* window, const Mesh& mesh, const Camera& camera, const SceneViewData& data,
                  const SceneViewOptions& options);

// A 2D view (matrix, hemicube faces, Nusselt disk, visibility) as a renderer holding a context actor: the
// drawing is fitted to the renderer's size, so it follows the host window.
vtkSmartPointer<vtkRenderer> makeDrawingRenderer(const Drawing& drawing);

}  // namespace rt::viz
