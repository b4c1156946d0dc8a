// What `radiosity figure` draws, as data: the view, its size, the numbers behind it (form-factor method,
// solver, resolution...) and the view's own choices. The command line fills it from its options; drawFigure
// (viz/figure_driver.h) draws it. No CLI types, so the same request can come from a test or a lesson.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/refine/refine.h"

namespace rt::viz {

// The views `radiosity figure` draws, in the order `--help` lists them (here, not in the driver, so that a
// build without the viz library still parses the option and says it cannot draw).
inline const std::vector<std::string>& figureViewNames() {
  static const std::vector<std::string> names{"scene",  "formfactor", "hemicube",    "nusselt",
                                              "rays",   "matrix",     "convergence", "runtime-error",
                                              "energy", "visibility", "links",       "discontinuity"};
  return names;
}

struct FigureRequest {
  std::string view = "scene", output;  // see figureViewNames(); output: .png, .svg or .pdf
  int width = 1200, height = 900;
  double dpi = 96;
  // The form-factor method: the caller sets it (the CLI from the table of step keys, which holds the
  // default).
  std::string formFactors, referenceFormFactors, solver;
  int resolution = 128, samples = 16, maxIterations = 0;
  double formFactorTolerance = 0;  // quadrature / exact; 0: the method's own
  // Whether the reader gave these (otherwise each view picks a telling default).
  bool solverGiven = false, iterationsGiven = false, referenceGiven = false, resolutionGiven = false,
       samplesGiven = false, colourGiven = false;
  // scene view
  std::string colour = "radiosity", toneMap = "linear", colourMap = "viridis", errorMeasure = "relative";
  double exposure = 0;
  bool smooth = false, edges = false, noGamma = false, logScale = false, noColourBar = false;
  // element choice and the other views
  int element = -1, target = -1, row = -1, column = -1;
  int channel = 1;  // 0 red, 1 green, 2 blue
  std::string matrix = "F", part = "auto", xAxis = "iteration";
  std::vector<std::string> solvers;
  std::string input;  // runtime-error: a timing table measured earlier
  // Meshes that follow the light: scene (refineMode), links (hierarchical), discontinuity.
  std::string refineMode, linkColour = "level";
  RefineOptions refine;
  // One line per step worth telling (form factors computed, the Nusselt area, the visible fraction).
  std::function<void(const std::string&)> note;
  Progress* progress = nullptr;  // null: none
};

}  // namespace rt::viz
