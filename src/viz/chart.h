// Line charts (convergence, run time against error, energy per bounce) written as PNG, or as true vector
// SVG/PDF. Public header: no VTK types.
#pragma once

#include <string>
#include <vector>

namespace rt::viz {

struct Series {
  std::string name;
  std::vector<double> x, y;
  // The index (in the same chart) of the series this one is fitted to, or -1. A fit is drawn dashed and thin,
  // in its series' colour and without markers, under the measured curves and without a legend entry of its
  // own: the measured series' name carries what the fit says (its order or slope).
  int fitOf = -1;
};

// printf-style text of one number (a chart's legend or a figure's caption), e.g. formatted("%.2f", slope).
std::string formatted(const char* format, double value);

// The straight line of log-log slope `slope` through the centre of mass (in log-log) of `points`, drawn over
// their first and last x: a fitted power law for a chart, fitted to the series at index `fitOf`. `points`
// must have two or more points.
Series fittedPowerLaw(const Series& points, double slope, int fitOf);

struct ChartOptions {
  std::string title, xLabel, yLabel;
  bool logX = false, logY = false;
  int width = 1200, height = 800;
  double dpi = 96.0;  // scales fonts and line widths (dpi / 96)
  // A marker at every data point (distinguishes curves in grey print too), on the series whose points stand
  // apart by two and a half marker widths or more.
  bool markers = true;
};

// The format follows the extension: .png (raster), .svg and .pdf (vectors). Series get colour-blind-safe
// colours (Okabe-Ito) and distinct markers. On a log axis, points with a value <= 0 are left out (they have
// no position). Throws std::invalid_argument when nothing can be drawn, std::runtime_error when the file
// cannot be written.
void writeLineChart(const std::vector<Series>& series, const ChartOptions& options, const std::string& path);

}  // namespace rt::viz
