// The convergence chart beside an iterative step: relative residual against iteration on a log axis, drawn up
// to the iteration being shown (so it grows while the replay plays), the whole curve faint behind it. A
// compare pane's run is a second curve.
#pragma once

#include <QChartView>
#include <QFont>
#include <QString>
#include <array>
#include <vector>

class QLineSeries;
class QLogValueAxis;
class QValueAxis;
class QScatterSeries;

namespace rt::app {

class ResidualChart : public QChartView {
  Q_OBJECT
 public:
  explicit ResidualChart(QWidget* parent = nullptr);

  // One or two runs: residual per recorded iteration. Empty clears the chart.
  void setRuns(const std::vector<QString>& names, const std::vector<std::vector<double>>& residuals);
  // Shows the curves up to `index` (0-based).
  void setCurrent(int index);
  int pointsShown(int run) const;
  void setLargeFonts(bool large);
  // The axes' label font (presenter mode makes it larger; leaving gives the normal one back).
  QFont labelsFont() const;
  // The x axis's title font (bold, as Qt Charts sets axis titles, in both modes).
  QFont axisTitleFont() const;
  // How many labels the residual axis shows; fewer than its decades when the chart is short (one label per
  // decade would not fit, and Qt Charts would write each as "...").
  int residualLabels() const;

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  void fitResidualLabels();

  std::vector<std::vector<double>> residuals_;
  std::vector<QLineSeries*> full_, shown_;
  QScatterSeries* marker_ = nullptr;
  QValueAxis* xAxis_ = nullptr;
  QLogValueAxis* yAxis_ = nullptr;
  bool large_ = false;
  // Where a zero residual is drawn: a decade under the lowest positive one of the runs (found in setRuns, so
  // that the replay's many setCurrent calls do not scan every run again).
  double floor_ = 1e-7;
  // The residual axis's range, as powers of ten.
  int lowestDecade_ = -6, highestDecade_ = 0;
  // The fonts of the normal mode: chart title, x and y labels, x and y titles, legend.
  std::array<QFont, 6> normalFonts_;
  bool normalFontsKnown_ = false;
};

}  // namespace rt::app
