// Heat map of a matrix (form factors F, the system matrix K = I - diag(rho) F, or a difference of two): log
// or linear colour scale, separators between element groups (patches or surfaces), a highlighted row/column,
// and the numbers in the cells when the matrix is small. A 2D view: PNG, or true vectors in SVG and PDF.
// Public header: no VTK.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "viz/colour_map.h"
#include "viz/drawing.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct MatrixViewOptions {
  FigureSize size{1000, 860, 96.0};
  std::string title = "Form factors F_ij";
  std::string rowLabel = "i (emitting element)";
  std::string columnLabel = "j (receiving element)";
  std::string valueLabel = "F_ij";
  bool logScale = true;  // log10 of |value| over at most 6 decades below the largest (unless min is given);
                         // exact zeros get a light grey so that "nothing" stays distinct from "small"
  ColourMap map = ColourMap::Viridis;
  std::vector<int> groups;  // one label per element (e.g. its patch); a separator where the label changes
  int selectedRow = -1, selectedColumn = -1;
  int maxCells = 160;    // larger matrices are shown as blocks (the largest |value| of each block)
  int numbersUpTo = 12;  // the values are printed in the cells when n <= this
  double min = std::numeric_limits<double>::quiet_NaN(), max = std::numeric_limits<double>::quiet_NaN();
};

// The figure as shapes (pure): tests count cells, separators and numbers.
Drawing matrixDrawing(const Eigen::MatrixXd& matrix, const MatrixViewOptions& options);
void writeMatrixFigure(const Eigen::MatrixXd& matrix, const MatrixViewOptions& options,
                       const std::string& path);

}  // namespace rt::viz
