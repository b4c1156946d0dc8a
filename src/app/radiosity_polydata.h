// Turning a solved mesh into what VTK draws: one polygon per element, coloured per cell by its displayed
// radiosity (exposure, clamp, sRGB gamma), with the element index kept as cell data so that a pick maps back
// to the element.
#pragma once

#include <vtkSmartPointer.h>

#include "core/mesh.h"

class vtkPolyData;

namespace rt::app {

struct DisplayOptions {
  double exposure = 0.0;  // multiplier on B; 0 = automatic (the brightest non-emitting element maps to 1)
  bool reinhard = false;  // tone map x / (1 + x) instead of clamping
  bool gamma = true;      // sRGB transfer curve
};

// The automatic exposure: 1 / (largest channel of B over elements that do not emit), so reflected light fills
// the range and emitters saturate, as they do in a photograph.
double automaticExposure(const Mesh& mesh, const RgbField& B);

// Display colour of every element, 0..255 per channel (n x 3).
Eigen::Matrix<unsigned char, Eigen::Dynamic, 3> displayColours(const Mesh& mesh, const RgbField& B,
                                                               const DisplayOptions& options);

// Cell data: "Colors" (unsigned char RGB, active scalars) and "ElementId" (int).
vtkSmartPointer<vtkPolyData> makeRadiosityPolyData(const Mesh& mesh, const RgbField& B,
                                                   const DisplayOptions& options);

}  // namespace rt::app
