// What an elements step measures: the constant and the linear basis on each of the step's `subdivisions`,
// their error against a fine reference (the linear basis on the step's own mesh) point by point, over the
// whole scene and over each highlighted surface, and the fitted convergence orders. The viz layer draws
// them; the numbers are also the step's placeholders.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rt::lesson {

struct BasisErrorPoint {
  int subdivide = 0;
  long elements = 0;
  long unknowns = 0;                           // elements (constant) or nodes (linear)
  double error = 0;                            // relative L1 error over the scene
  std::map<std::string, double> surfaceError;  // the same over each highlighted surface
};

struct BasisSeries {
  std::string basis;  // "constant" or "linear"
  std::vector<BasisErrorPoint> points;
  double order = 0;  // the fitted order p of error ~ h^p, h ~ 1 / subdivide
  std::map<std::string, double> surfaceOrder;
};

struct ElementsData {
  std::vector<BasisSeries> series;
  std::vector<std::string> surfaces;  // the highlighted surfaces, each measured on its own
  int referenceSubdivide = 0;
  long referenceElements = 0;
};

}  // namespace rt::lesson
