// Line charts (convergence, run time against error, energy per bounce) written as PNG, or as true vector SVG/PDF.
// Public header: no VTK types.
#pragma once

#include <string>
#include <vector>

namespace rt::viz {

struct Series {
  std::string name;
  std::vector<double> x, y;
};

struct ChartOptions {
  std::string title, xLabel, yLabel;
  bool logX = false, logY = false;
  int width = 1200, height = 800;
};

// The format follows the extension: .png (raster), .svg and .pdf (vectors). Throws std::runtime_error on failure.
void writeLineChart(const std::vector<Series>& series, const ChartOptions& options, const std::string& path);

}  // namespace rt::viz
