// Images side by side under their titles: the path-traced, radiosity and two-pass pictures of a scene, or
// their difference maps with one colour bar. Built as a Drawing (tests inspect it), written as PNG, SVG or
// PDF. Public header: no VTK types.
#pragma once

#include <string>
#include <vector>

#include "core/io/rgb_image.h"
#include "viz/display_pipeline.h"
#include "viz/drawing.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct ImagePanel {
  std::string title;
  RgbImage image;  // linear W/m^2
};

struct ImagePanelsOptions {
  FigureSize size;
  std::string title;
  // Pictures: one exposure for every panel (0: automatic, from the first panel), tone map and gamma.
  double exposure = 0;
  ToneMap toneMap = ToneMap::LinearClamp;
  bool srgbGamma = true;
  // Difference maps instead: each pixel's mean over channels divided by `scale`, coloured on `map` from 0 to
  // `full`, with a colour bar titled `legend`.
  bool scalar = false;
  double scale = 1, full = 0.2;
  ColourMap map = ColourMap::Viridis;
  std::string legend;
};

// The exposure the pictures share when options.exposure is 0: the 98th percentile of the first panel's
// brightest channel maps to white (as the scene views expose, so that the light does not darken the room).
double panelExposure(const std::vector<ImagePanel>& panels, const ImagePanelsOptions& options);

Drawing imagePanelsDrawing(const std::vector<ImagePanel>& panels, const ImagePanelsOptions& options);
// Throws std::invalid_argument without panels, std::runtime_error when the file cannot be written.
void writeImagePanelsFigure(const std::vector<ImagePanel>& panels, const ImagePanelsOptions& options,
                            const std::string& path);

}  // namespace rt::viz
