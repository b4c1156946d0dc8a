// The elements of a mesh as VTK polygons for the 3D views, built once per mesh and recoloured in place: a
// replay step, a new tone map or another colouring rewrites one array of bytes, and the renderer re-uploads
// that array alone (VTK keeps a buffer per array and the triangulated index buffer while the cells are
// unchanged). At a million elements a rebuild of the whole polydata costs seconds; a recolour does not.
// Includes VTK: viz sources and the app only.
#pragma once

#include <vtkSmartPointer.h>

#include "viz/scene_view.h"

class vtkPolyData;

namespace rt::viz {

// One polygon per element, cell i being element i; points repeated per element corner (in the order of
// ScenePaint's corners) so that corners can differ in colour. Cell data "element" (the element index), point
// data "colour" (RGB, unsigned char) from the paint, grey without one. Coordinates in single precision, as
// the renderer takes them.
vtkSmartPointer<vtkPolyData> makeElementPolyData(const Mesh& mesh, const ScenePaint& paint);

// Writes `paint`'s colours (grey without paint) into the "colour" array of `data`, made by
// makeElementPolyData for the same mesh, and marks that array modified. Throws std::invalid_argument when
// the paint's corners do not fit the data.
void updateElementColours(vtkPolyData& data, const ScenePaint& paint);

}  // namespace rt::viz
