#include "app/residual_chart.h"

#include <QChart>
#include <QFontMetricsF>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>
#include <algorithm>
#include <array>
#include <cmath>

namespace rt::app {
namespace {

// Log axes cannot show 0: residuals that reached exactly zero are drawn at a floor below the smallest
// positive one.
double plotted(double value, double floor) {
  return value > floor ? value : floor;
}

const QColor kRunColours[] = {QColor(0, 114, 178),
                              QColor(213, 94, 0)};  // colour-blind-safe blue and vermilion

}  // namespace

ResidualChart::ResidualChart(QWidget* parent) : QChartView(parent) {
  auto* chart = new QChart();
  chart->setMargins(QMargins(4, 4, 4, 4));
  chart->legend()->setAlignment(Qt::AlignBottom);
  xAxis_ = new QValueAxis(chart);
  xAxis_->setTitleText(tr("iteration"));
  xAxis_->setLabelFormat("%d");
  yAxis_ = new QLogValueAxis(chart);
  yAxis_->setTitleText(tr("relative residual"));
  yAxis_->setLabelFormat("%.0e");
  yAxis_->setBase(10);
  chart->addAxis(xAxis_, Qt::AlignBottom);
  chart->addAxis(yAxis_, Qt::AlignLeft);
  setChart(chart);
  setRenderHint(QPainter::Antialiasing);
  setMinimumHeight(160);
}

void ResidualChart::setRuns(const std::vector<QString>& names,
                            const std::vector<std::vector<double>>& residuals) {
  QChart* c = chart();
  for (auto* s : full_) c->removeSeries(s), delete s;
  for (auto* s : shown_) c->removeSeries(s), delete s;
  if (marker_) c->removeSeries(marker_), delete marker_;
  full_.clear();
  shown_.clear();
  marker_ = nullptr;
  residuals_ = residuals;

  double lowest = 1e300, highest = 0;
  int longest = 1;
  for (const auto& run : residuals_) {
    longest = std::max(longest, static_cast<int>(run.size()));
    for (double r : run)
      if (r > 0 && std::isfinite(r)) lowest = std::min(lowest, r), highest = std::max(highest, r);
  }
  if (highest <= 0) lowest = 1e-6, highest = 1;
  floor_ = lowest / 10;
  const double floor = floor_;
  for (std::size_t k = 0; k < residuals_.size(); ++k) {
    const QColor colour = kRunColours[k % 7];
    auto* full = new QLineSeries();
    auto* shown = new QLineSeries();
    full->setName(k < names.size() ? names[k] + tr(" (all)") : QString());
    shown->setName(k < names.size() ? names[k] : QString());
    QColor faint = colour;
    faint.setAlpha(60);
    full->setPen(QPen(faint, 2));
    shown->setPen(QPen(colour, 3));
    for (std::size_t i = 0; i < residuals_[k].size(); ++i)
      full->append(static_cast<double>(i + 1), plotted(residuals_[k][i], floor));
    for (QLineSeries* s : {full, shown}) {
      c->addSeries(s);
      s->attachAxis(xAxis_);
      s->attachAxis(yAxis_);
    }
    c->legend()->markers(full).first()->setVisible(false);
    full_.push_back(full);
    shown_.push_back(shown);
  }
  marker_ = new QScatterSeries();
  marker_->setMarkerSize(10);
  marker_->setColor(large_ ? QColor(255, 255, 255) : QColor(0, 0, 0));
  c->addSeries(marker_);
  marker_->attachAxis(xAxis_);
  marker_->attachAxis(yAxis_);
  c->legend()->markers(marker_).first()->setVisible(false);
  xAxis_->setRange(1, std::max(2, longest));
  // Whole-number ticks: an interval that gives at most about eight of them.
  xAxis_->setTickType(QValueAxis::TicksDynamic);
  xAxis_->setTickAnchor(1);
  xAxis_->setTickInterval(std::max(1, (longest + 7) / 8));
  lowestDecade_ = static_cast<int>(std::floor(std::log10(floor)));
  highestDecade_ = std::max(lowestDecade_ + 1, static_cast<int>(std::ceil(std::log10(highest))));
  yAxis_->setRange(std::pow(10, lowestDecade_), std::pow(10, highestDecade_));
  fitResidualLabels();
  c->legend()->setVisible(residuals_.size() > 1);
  // Empty axes alone would look like a solver that failed to start.
  c->setTitle(residuals_.empty() ? tr("No iteration history in this step") : QString());
  setCurrent(longest - 1);
}

void ResidualChart::setCurrent(int index) {
  if (!marker_) return;
  marker_->clear();
  for (std::size_t k = 0; k < residuals_.size(); ++k) {
    QList<QPointF> points;
    const int last = std::min(index, static_cast<int>(residuals_[k].size()) - 1);
    for (int i = 0; i <= last; ++i) points.append(QPointF(i + 1, plotted(residuals_[k][i], floor_)));
    shown_[k]->replace(points);
    if (last >= 0) marker_->append(points.back());
  }
}

int ResidualChart::pointsShown(int run) const {
  return run < static_cast<int>(shown_.size()) ? static_cast<int>(shown_[run]->count()) : 0;
}

QFont ResidualChart::labelsFont() const {
  return xAxis_->labelsFont();
}

void ResidualChart::setLargeFonts(bool large) {
  large_ = large;
  // Presenter mode: the chart follows the high-contrast palette (white on black).
  const QColor background = large ? QColor(0, 0, 0) : QColor(255, 255, 255);
  const QColor foreground = large ? QColor(255, 255, 255) : QColor(0, 0, 0);
  chart()->setBackgroundBrush(background);
  for (QAbstractAxis* axis : {static_cast<QAbstractAxis*>(xAxis_), static_cast<QAbstractAxis*>(yAxis_)}) {
    axis->setLabelsBrush(foreground);
    axis->setTitleBrush(foreground);
  }
  chart()->legend()->setLabelColor(foreground);
  if (marker_) marker_->setColor(foreground);
  // From the chart's own normal fonts, each kept as it was (the axis titles are bold, the labels not), not
  // from the widget's: in presenter mode the application font is already larger, and leaving must give back
  // exactly the fonts the chart had.
  QAbstractAxis* axes[] = {xAxis_, yAxis_};
  if (!normalFontsKnown_) {
    normalFonts_ = {chart()->titleFont(), xAxis_->labelsFont(), yAxis_->labelsFont(),
                    xAxis_->titleFont(),  yAxis_->titleFont(),  chart()->legend()->font()};
    normalFontsKnown_ = true;
  }
  std::array<QFont, 6> fonts = normalFonts_;
  if (large)
    for (QFont& font : fonts) font.setPointSizeF(std::max(font.pointSizeF(), 9.0) * 1.8);
  chart()->setTitleFont(fonts[0]);
  for (int k = 0; k < 2; ++k) {
    axes[k]->setLabelsFont(fonts[1 + k]);
    axes[k]->setTitleFont(fonts[3 + k]);
  }
  chart()->legend()->setFont(fonts[5]);
  fitResidualLabels();
}

void ResidualChart::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  fitResidualLabels();
}

void ResidualChart::fitResidualLabels() {
  // A label needs its line and a little air; the plot area is the chart's height less the x axis and the
  // legend (estimated before the first layout, when the chart has no plot area yet).
  const double labelHeight = 1.4 * QFontMetricsF(yAxis_->labelsFont()).height();
  double room = chart()->plotArea().height();
  if (room <= 0) room = height() - 4 * labelHeight;
  const int fit = std::max(2, static_cast<int>(room / labelHeight));
  const int decades = highestDecade_ - lowestDecade_;
  const int perLabel = std::max(1, (decades + fit - 2) / (fit - 1));
  // The axis labels the powers of its base inside its range: base 10^k labels every k-th decade.
  yAxis_->setBase(std::pow(10.0, perLabel));
  yAxis_->setMinorTickCount(perLabel > 1 ? perLabel - 1 : 0);
}

int ResidualChart::residualLabels() const {
  const int perLabel = static_cast<int>(std::lround(std::log10(yAxis_->base())));
  return (highestDecade_ - lowestDecade_) / std::max(1, perLabel) + 1;
}

QFont ResidualChart::axisTitleFont() const {
  return xAxis_->titleFont();
}

}  // namespace rt::app
