// Rendering the window into a PNG without a person at the screen (`--screenshot`), and the pixel statistics
// tests use to tell a real VTK image from the classic black failure of a GL widget.
#pragma once

#include <QImage>
#include <QRect>
#include <QString>

class QWidget;

namespace rt::app {

struct PixelStatistics {
  double meanLuminance = 0;  // 0..255
  double stdDevLuminance = 0;
  int distinctColours = 0;  // capped at 4096
  double nonBlackFraction = 0;
};

PixelStatistics pixelStatistics(const QImage& image, const QRect& area = QRect());

// Makes sure every GL widget has painted, then grabs `window`. Throws std::runtime_error when it cannot save.
QImage grabWindow(QWidget& window);
void saveScreenshot(QWidget& window, const QString& path);

}  // namespace rt::app
