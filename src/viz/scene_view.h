// The scene view: elements drawn as polygons from a camera, coloured by radiosity (through the display
// pipeline), by material (reflectance, emission), by element id, or by a scalar (unshot power, error against
// a reference, a form-factor row...) through a colour-blind-safe map with a colour bar. Public header: no VTK
// types (viz/vtk_views.h has the VTK-facing builders for the app).
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/scene.h"
#include "viz/colour_map.h"
#include "viz/figure_output.h"
#include "viz/scene_image.h"
#include "viz/vertex_interpolation.h"

namespace rt::viz {

enum class SceneColouring { Radiosity, Reflectance, Emission, ElementId, UnshotPower, Error, Scalar };
// "radiosity", "reflectance", "emission", "element", "unshot", "error", "scalar"; throws
// std::invalid_argument.
SceneColouring sceneColouringFromName(const std::string& name);
std::string toString(SceneColouring colouring);

// How the Error colouring measures the difference to the reference. Relative is the default: an absolute
// error of 1 W/m^2 is large in a shadow and invisible next to the light, and the eye judges ratios. But a
// nearly unlit element's ratio can be 25 with a difference nobody sees, and then it alone sets the colour
// bar: OfBrightest divides by the brightest reflecting element of the reference instead, the measure the
// lessons quote ("19.6 % of the brightest reflecting element").
enum class ErrorMeasure { Relative, Absolute, OfBrightest };
// "relative", "absolute", "brightest"; throws std::invalid_argument.
ErrorMeasure errorMeasureFromName(const std::string& name);

// How a scalar field is mapped to colour and labelled on its colour bar. Non-finite limits: from the data.
struct ScalarLegend {
  std::string title;
  ColourMap map = ColourMap::Viridis;
  bool logScale = false;  // log10; values <= 0 get the lowest colour
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
};

// The data the colourings read; only what the chosen colouring needs has to be filled.
struct SceneViewData {
  RgbField B;              // Radiosity, Error (n x 3, W/m^2)
  RgbField unshot;         // UnshotPower: unshot radiosity (n x 3)
  RgbField reference;      // Error: the reference radiosity
  Eigen::VectorXd scalar;  // Scalar: one value per element
  // Radiosity of a linear basis: its values at every element corner (LinearBasis::cornerValues, the mesh's
  // corner order), drawn as they are and never smoothed; B then holds the element averages.
  RgbField corners;
};

struct SceneViewOptions {
  SceneColouring colouring = SceneColouring::Radiosity;
  ErrorMeasure errorMeasure = ErrorMeasure::Relative;  // Error colouring
  ImageOptions image;   // size, exposure, tone map, gamma, smooth (per-vertex) shading, mesh edges
  ScalarLegend legend;  // scalar colourings (a title is chosen when empty)
  bool colourBar = true;
  std::string caption;  // drawn at the top; empty: none
  int highlightElement =
      -1;  // filled with a marker colour and outlined (e.g. the source of a form-factor row)
  std::array<double, 3> edgeColour = {0.08, 0.08, 0.08};  // the mesh edges (image.showEdges)
  double edgeWidth = 1.0;                                 // pixels at 96 dpi (never under one pixel)
  double dpi = 96.0;
};

// What the renderer draws: one 8-bit sRGB colour per element corner (flat views repeat the element's colour),
// and the colour bar when the view is scalar. Pure (no VTK): tests check it directly.
struct ScenePaint {
  std::vector<int> firstCorner;  // corner k of element e is colours[firstCorner[e] + k]
  std::vector<Rgb8> colours;
  bool colourBar = false;
  ScalarLegend legend;  // resolved: finite min and max
  int highlightElement = -1;
};
// `smoothing` (optional): the smooth scheme's structure of this mesh, found once by the caller (the app's
// view keeps it while it replays iterations); without it smooth views find it on every call.
ScenePaint paintScene(const Mesh& mesh, const SceneViewData& data, const SceneViewOptions& options,
                      const SmoothInterpolation* smoothing = nullptr);

// Scalar fields for the colourings (one value per element).
Eigen::VectorXd unshotPower(const Mesh& mesh,
                            const RgbField& unshot);  // mean over channels of unshot_i A_i (W)
Eigen::VectorXd absoluteError(const RgbField& B,
                              const RgbField& reference);  // mean over channels of |B - B_ref|
// Mean over channels of |B - B_ref| divided by the mean over channels of B_ref. References at or near zero
// (an unlit element) would divide by zero: the denominator is at least 1e-3 x the area-free mean of the
// reference over all elements, so such elements show a large but finite error.
Eigen::VectorXd relativeError(const RgbField& B, const RgbField& reference);
// Mean over channels of |B - B_ref| divided by the largest mean over channels of B_ref among the elements
// that emit nothing (the light would set the scale otherwise).
Eigen::VectorXd errorOfBrightest(const Mesh& mesh, const RgbField& B, const RgbField& reference);

// Renders the view and writes PNG, or PDF/SVG embedding the rendered image. Throws std::runtime_error on
// failure and std::invalid_argument when the data does not fit the mesh.
void writeSceneFigure(const Mesh& mesh, const Camera& camera, const SceneViewData& data,
                      const SceneViewOptions& options, const std::string& path);

}  // namespace rt::viz
