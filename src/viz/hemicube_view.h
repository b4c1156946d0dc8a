// The hemicube of one element: its five faces unfolded around the top face in 2D (delta form factors as a
// heat map, or the item buffer: which element every pixel sees), and the half cube over the element in 3D
// with its pixels coloured by the item buffer. The data are core's (renderHemicube, deltaFormFactors in
// core/formfactor/hemicube.h). 2D: PNG or true vectors; 3D: PNG, PDF/SVG embed the image. Public header: no
// VTK.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/formfactor/hemicube.h"
#include "core/scene.h"
#include "viz/drawing.h"
#include "viz/figure_output.h"

namespace rt::viz {

enum class HemicubeColouring { DeltaFormFactors, ItemBuffer };
HemicubeColouring hemicubeColouringFromName(const std::string& name);  // "delta", "items"

struct HemicubeViewOptions {
  FigureSize size{1100, 1000, 96.0};
  HemicubeColouring colouring = HemicubeColouring::ItemBuffer;
  ColourMap map = ColourMap::Viridis;  // delta form factors
  int legendEntries = 10;              // item buffer: the elements with the largest form factors are listed
  std::string title;                   // empty: chosen
};

// The four corners of a pixel in the element's local frame (x along u, y along v, z along the normal; the eye
// at the origin, the cube of half-size 1), in the buffer convention of core/formfactor/hemicube.h.
std::array<Vec3, 4> hemicubePixelCorners(HemicubeFace face, int row, int column, int resolution);
// Where a point of a face lands in the unfolded net: the top face is [-1,1]^2, the sides fold out around it.
Vec2 unfoldHemicubePoint(HemicubeFace face, const Vec3& local);

Drawing hemicubeFacesDrawing(const HemicubeFaces& faces, std::size_t elements,
                             const HemicubeViewOptions& options);
void writeHemicubeFacesFigure(const HemicubeFaces& faces, std::size_t elements,
                              const HemicubeViewOptions& options, const std::string& path);
// The half cube over the element, its pixels coloured by the element they see, in the scene seen from
// `camera`.
void writeHemicube3dFigure(const Mesh& mesh, const HemicubeFaces& faces, const HemicubeViewOptions& options,
                           const std::string& path);

}  // namespace rt::viz
