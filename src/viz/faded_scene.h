// The scene drawn faintly by reflectance, with its mesh edges, so that the rays drawn inside it stay
// visible: the backdrop of the 3D ray views (local lines, sample rays, a ray tree). Includes VTK: viz
// sources only.
#pragma once

#include <vtkSmartPointer.h>

#include "core/mesh.h"
#include "core/scene.h"
#include "viz/figure_output.h"

class vtkRenderer;
class vtkRenderWindow;

namespace rt::viz {

// Adds the faded scene's renderer to `window` over `viewport` (xmin, ymin, xmax, ymax in normalised window
// coordinates; null: the whole window) and returns it.
vtkSmartPointer<vtkRenderer> addFadedScene(const Mesh& mesh, const Camera& camera, const FigureSize& size,
                                           vtkRenderWindow* window, const double* viewport = nullptr);

}  // namespace rt::viz
