// What VTK 9.1's vtkSVGExporter writes that SVG reads otherwise than VTK drew it, repaired in one place:
// every SVG of a 2D view passes through repairVtkSvg after the export (vtk_render.cpp). The exporter has no
// option for any of these; each repair names the exporter's slip it undoes.
#pragma once

#include <string>

namespace rt::viz {

// Clips in page units; text anchored, turned, placed on its baseline, sized and as wide as VTK drew it.
void repairVtkSvg(std::string& svg);

}  // namespace rt::viz
