#include "viz/chart.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContext2D.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPlotLine.h>
#include <vtkPoints2D.h>
#include <vtkRect.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkTransform2D.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "viz/colour_map.h"
#include "viz/vtk_render.h"

namespace rt::viz {
namespace {

// A chart's curve drawn in page units. vtkChartXY paints a plot under the transform from data to page units,
// and VTK 9.1's SVG and PDF devices stroke under that transform too: a pen of 2.5 pixels becomes 2.5 data
// units scaled to the page, a band wherever one axis spans a small range, and the markers turn to ellipses.
// The points are mapped to the page here and drawn under the identity, so that every device (OpenGL for PNG
// alike) strokes the curve with the pen's own width.
class PageUnitsLine : public vtkPlotLine {
 public:
  static PageUnitsLine* New();

  bool Paint(vtkContext2D* painter) override {
    if (!Points || Points->GetNumberOfPoints() == 0) return vtkPlotLine::Paint(painter);
    const auto n = static_cast<int>(Points->GetNumberOfPoints());
    auto* xy = static_cast<float*>(Points->GetVoidPointer(0));
    const std::vector<float> data(xy, xy + 2 * static_cast<std::size_t>(n));
    painter->GetTransform()->TransformPoints(data.data(), xy, n);
    painter->PushMatrix();
    auto identity = vtkSmartPointer<vtkTransform2D>::New();
    painter->SetTransform(identity);
    const bool painted = vtkPlotLine::Paint(painter);
    painter->PopMatrix();
    std::copy(data.begin(), data.end(), xy);  // the chart keeps its points in data units
    return painted;
  }

  vtkTypeMacro(PageUnitsLine, vtkPlotLine)
};
vtkStandardNewMacro(PageUnitsLine);

void styleAxis(vtkAxis* axis, const std::string& title, bool logScale, int fontSize) {
  axis->SetTitle(title);
  axis->SetLogScale(logScale);
  axis->GetTitleProperties()->SetFontSize(fontSize);
  axis->GetTitleProperties()->SetColor(0.1, 0.1, 0.1);
  axis->GetTitleProperties()->BoldOff();
  axis->GetLabelProperties()->SetFontSize(static_cast<int>(fontSize * 0.85));
  axis->GetLabelProperties()->SetColor(0.1, 0.1, 0.1);
  axis->GetGridPen()->SetColor(215, 215, 215, 255);
  axis->SetBehavior(vtkAxis::AUTO);
}

}  // namespace

std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

Series fittedPowerLaw(const Series& points, double slope, int fitOf) {
  double lx = 0, ly = 0;
  const double count = static_cast<double>(points.x.size());
  for (std::size_t k = 0; k < points.x.size(); ++k) {
    lx += std::log(points.x[k]) / count;
    ly += std::log(points.y[k]) / count;
  }
  Series fitted{points.name + " (fit)", {}, {}, fitOf};
  for (double x : {points.x.front(), points.x.back()}) {
    fitted.x.push_back(x);
    fitted.y.push_back(std::exp(ly + slope * (std::log(x) - lx)));
  }
  return fitted;
}

namespace {

// Whether a point has a place on the chart: finite, and positive on a log axis.
bool drawable(double x, double y, const ChartOptions& options) {
  return std::isfinite(x) && std::isfinite(y) && !(options.logX && x <= 0) && !(options.logY && y <= 0);
}

// The corner of the plot whose legend would cover the fewest stretches of curve: the curves' points and the
// points between them, on the chart's (log) scales, counted in a box of the legend's rough size in each
// corner. Ties keep the top right. Returns {horizontal, vertical} vtkChartLegend alignments.
std::pair<int, int> emptiestCorner(const std::vector<Series>& series, const ChartOptions& options) {
  auto scaled = [](double v, bool log) { return log ? std::log10(v) : v; };
  std::vector<std::pair<double, double>> points;
  std::size_t entries = 0, longest = 0;
  for (const Series& one : series) {
    if (one.fitOf < 0) {
      ++entries;
      longest = std::max(longest, one.name.size());
    }
    const std::size_t n = std::min(one.x.size(), one.y.size());
    for (std::size_t k = 0; k < n; ++k) {
      if (!drawable(one.x[k], one.y[k], options)) continue;
      const double x = scaled(one.x[k], options.logX), y = scaled(one.y[k], options.logY);
      if (k + 1 == n || !drawable(one.x[k + 1], one.y[k + 1], options)) {
        points.emplace_back(x, y);
        continue;
      }
      const double x1 = scaled(one.x[k + 1], options.logX), y1 = scaled(one.y[k + 1], options.logY);
      for (int t = 0; t < 8; ++t) points.emplace_back(x + (x1 - x) * t / 8.0, y + (y1 - y) * t / 8.0);
    }
  }
  const int top = vtkChartLegend::TOP, right = vtkChartLegend::RIGHT;
  if (points.empty()) return {right, top};
  double x0 = points[0].first, x1 = x0, y0 = points[0].second, y1 = y0;
  for (const auto& [x, y] : points) {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  // The legend's share of the plot: about 0.55 em per character beside a marker, 1.5 em per entry.
  const double em = 0.03 * options.height * 0.85;
  const double w = std::min(0.6, (static_cast<double>(longest) * 0.55 * em + 3 * em) / (0.8 * options.width));
  const double h = std::min(0.6, (static_cast<double>(entries) * 1.5 * em + em) / (0.75 * options.height));
  std::pair<int, int> best{right, top};
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  for (const int vertical : {top, static_cast<int>(vtkChartLegend::BOTTOM)})
    for (const int horizontal : {right, static_cast<int>(vtkChartLegend::LEFT)}) {
      std::size_t covered = 0;
      for (const auto& [x, y] : points) {
        const double u = x1 > x0 ? (x - x0) / (x1 - x0) : 0.5, v = y1 > y0 ? (y - y0) / (y1 - y0) : 0.5;
        const bool inX = horizontal == right ? u >= 1 - w : u <= w;
        const bool inY = vertical == top ? v >= 1 - h : v <= h;
        covered += inX && inY;
      }
      if (covered < fewest) {
        fewest = covered;
        best = {horizontal, vertical};
      }
    }
  return best;
}

}  // namespace

void writeLineChart(const std::vector<Series>& series, const ChartOptions& options, const std::string& path) {
  figureFormatOf(path);
  const double scale = options.dpi > 0 ? options.dpi / 96.0 : 1.0;
  const int fontSize = readableFontSize(options.height, scale, 0.03);

  auto view = vtkSmartPointer<vtkContextView>::New();
  view->SetRenderWindow(makeOffscreenWindow(options.width, options.height));
  view->GetRenderer()->SetBackground(1, 1, 1);
  auto chart = vtkSmartPointer<vtkChartXY>::New();
  view->GetScene()->AddItem(chart);
  chart->SetTitle(options.title);
  chart->GetTitleProperties()->SetFontSize(static_cast<int>(fontSize * 1.15));
  chart->GetTitleProperties()->SetColor(0.05, 0.05, 0.05);
  chart->GetTitleProperties()->BoldOn();
  styleAxis(chart->GetAxis(vtkAxis::BOTTOM), options.xLabel, options.logX, fontSize);
  styleAxis(chart->GetAxis(vtkAxis::LEFT), options.yLabel, options.logY, fontSize);

  static const int markers[] = {vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
                                vtkPlotPoints::CROSS, vtkPlotPoints::PLUS};
  // Okabe-Ito without its yellow (too light on white) until the other seven are used; a fit takes its
  // series' colour and marker slot.
  static const int order[] = {0, 1, 2, 4, 5, 6, 7, 3};
  std::vector<std::size_t> slot(series.size(), 0), drawingOrder;
  for (std::size_t s = 0, next = 0; s < series.size(); ++s)
    if (series[s].fitOf < 0) slot[s] = next++;
  for (std::size_t s = 0; s < series.size(); ++s) {
    const int of = series[s].fitOf;
    if (of >= static_cast<int>(series.size()) || (of >= 0 && series[of].fitOf >= 0))
      throw std::invalid_argument(path + ": series '" + series[s].name + "' is a fit to no measured series");
    if (of >= 0) {
      slot[s] = slot[of];
      drawingOrder.push_back(s);  // fits first, so that the measured curves are drawn over them
    }
  }
  for (std::size_t s = 0; s < series.size(); ++s)
    if (series[s].fitOf < 0) drawingOrder.push_back(s);
  int drawn = 0;
  for (const std::size_t s : drawingOrder) {
    const Series& one = series[s];
    const bool fit = one.fitOf >= 0;
    auto x = vtkSmartPointer<vtkDoubleArray>::New();
    x->SetName((one.name + " x").c_str());
    auto y = vtkSmartPointer<vtkDoubleArray>::New();
    y->SetName(one.name.empty() ? ("series " + std::to_string(s + 1)).c_str() : one.name.c_str());
    for (std::size_t k = 0; k < std::min(one.x.size(), one.y.size()); ++k) {
      if (!drawable(one.x[k], one.y[k], options)) continue;
      x->InsertNextValue(one.x[k]);
      y->InsertNextValue(one.y[k]);
    }
    if (x->GetNumberOfTuples() == 0) continue;
    auto table = vtkSmartPointer<vtkTable>::New();
    table->AddColumn(x);
    table->AddColumn(y);
    auto plot = vtkSmartPointer<PageUnitsLine>::New();
    chart->AddPlot(plot);
    plot->SetInputData(table, 0, 1);
    const Rgb8 colour = qualitativeColour(order[slot[s] % 8]);
    plot->SetColor(colour[0], colour[1], colour[2], 255);
    plot->SetWidth(static_cast<float>((fit ? 1.5 : 2.5) * scale));
    if (fit) {
      plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
      plot->SetLegendVisibility(false);
    }
    // Markers where they stand apart (two and a half marker widths per point across the figure): packed
    // closer they merge into a band wider than the line.
    const double markerSize = 7.0 * scale;
    const bool spaced = static_cast<double>(x->GetNumberOfTuples()) * 2.5 * markerSize <= options.width;
    plot->SetMarkerStyle(options.markers && spaced && !fit ? markers[slot[s] % 5] : vtkPlotPoints::NONE);
    plot->SetMarkerSize(static_cast<float>(markerSize));
    ++drawn;
  }
  if (drawn == 0) throw std::invalid_argument(path + ": no series has a point that can be drawn");
  chart->SetShowLegend(true);
  const auto [horizontal, vertical] = emptiestCorner(series, options);
  chart->GetLegend()->SetHorizontalAlignment(horizontal);
  chart->GetLegend()->SetVerticalAlignment(vertical);
  chart->GetLegend()->SetLabelSize(static_cast<int>(fontSize * 0.85));
  // VTK's 5 pixels around the labels are for its small default font: at these sizes a viewer whose sans serif
  // is wider than VTK's (rsvg, browsers) puts the longest label against the legend's border.
  chart->GetLegend()->SetPadding(std::max(5, static_cast<int>(fontSize / 3)));
  chart->GetLegend()->GetLabelProperties()->SetColor(0.05, 0.05, 0.05);
  if (figureFormatOf(path) != FigureFormat::Png) {
    // The plot area as laid out on screen, kept for the vector exporters: VTK 9.1's PDF device measures a
    // turned text as if it were level, and the y axis's title then takes its length, not its height, of the
    // page's width, pushing the plot to the right.
    view->GetRenderWindow()->Render();
    const int* low = chart->GetPoint1();
    const int* high = chart->GetPoint2();
    chart->SetLayoutStrategy(vtkChart::AXES_TO_RECT);
    chart->SetSize(vtkRectf(static_cast<float>(low[0]), static_cast<float>(low[1]),
                            static_cast<float>(high[0] - low[0]), static_cast<float>(high[1] - low[1])));
  }
  std::string description = "x: " + options.xLabel + "; y: " + options.yLabel + "; series:";
  for (const Series& s : series)
    if (s.fitOf < 0) description += " " + s.name + ",";
  description.pop_back();
  writeContextView(view, path, options.title, description);
}

}  // namespace rt::viz
