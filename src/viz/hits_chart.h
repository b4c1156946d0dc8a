// The local lines of one element counted per surface: for each surface a bar of the fraction of the lines
// that landed on it first, an error bar of two binomial standard errors either side, and a mark at the
// reference form factor, so that a reader sees at once which estimates are within their noise. Built as a
// Drawing (testable without VTK); written as PNG, SVG or PDF. Public header: no VTK.
#pragma once

#include <string>
#include <vector>

#include "viz/drawing.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct HitRow {
  std::string label;         // the surface
  double estimate = 0;       // N_ij / N
  double standardError = 0;  // sqrt(p (1 - p) / N)
  double reference = 0;      // F_ij by the reference method
};

struct HitsChartOptions {
  FigureSize size{1200, 800, 96.0};
  std::string title;
};

// Throws std::invalid_argument without rows.
Drawing hitsDrawing(const std::vector<HitRow>& rows, const HitsChartOptions& options);
void writeHitsChart(const std::vector<HitRow>& rows, const HitsChartOptions& options,
                    const std::string& path);

}  // namespace rt::viz
