#include "app/screenshot.h"

#include "app/lesson_text_view.h"

#include <QApplication>
#include <QOpenGLWidget>
#include <QSet>
#include <QWidget>
#include <cmath>
#include <stdexcept>

namespace rt::app {

PixelStatistics pixelStatistics(const QImage& input, const QRect& area) {
  const QImage image = input.convertToFormat(QImage::Format_RGB32);
  const QRect rect = area.isNull() ? image.rect() : area.intersected(image.rect());
  PixelStatistics stats;
  if (rect.isEmpty()) return stats;
  double sum = 0, sumSquares = 0;
  long nonBlack = 0;
  QSet<QRgb> colours;
  for (int y = rect.top(); y <= rect.bottom(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = rect.left(); x <= rect.right(); ++x) {
      const QRgb p = line[x];
      const double l = 0.2126 * qRed(p) + 0.7152 * qGreen(p) + 0.0722 * qBlue(p);
      sum += l;
      sumSquares += l * l;
      if (l > 8) ++nonBlack;
      if (colours.size() < 4096) colours.insert(p & 0xFFFFFF);
    }
  }
  const double n = static_cast<double>(rect.width()) * rect.height();
  stats.meanLuminance = sum / n;
  stats.stdDevLuminance =
      std::sqrt(std::max(0.0, sumSquares / n - stats.meanLuminance * stats.meanLuminance));
  stats.distinctColours = static_cast<int>(colours.size());
  stats.nonBlackFraction = nonBlack / n;
  return stats;
}

QImage grabWindow(QWidget& window) {
  // The text pane's page is typeset asynchronously: the picture waits for its maths.
  for (LessonTextView* text : window.findChildren<LessonTextView*>())
    if (text->isVisible()) text->waitUntilShown();
  // Two rounds of events: layouts settle, then every QOpenGLWidget runs paintGL into its framebuffer.
  for (int round = 0; round < 2; ++round) {
    QApplication::processEvents();
    for (QOpenGLWidget* gl : window.findChildren<QOpenGLWidget*>())
      if (gl->isVisible()) gl->repaint();
  }
  QApplication::processEvents();
  return window.grab().toImage();
}

void saveScreenshot(QWidget& window, const QString& path) {
  const QImage image = grabWindow(window);
  if (image.isNull() || !image.save(path, "PNG"))
    throw std::runtime_error("cannot write the screenshot " + path.toStdString());
}

}  // namespace rt::app
