#include "app/presenter_style.h"

#include <QApplication>

namespace rt::app {

AppLook currentLook() {
  return {QApplication::font(), QApplication::palette()};
}

void applyPresenterLook(const AppLook& normal, double scale) {
  QFont font = normal.font;
  if (font.pointSizeF() > 0)
    font.setPointSizeF(font.pointSizeF() * scale);
  else
    font.setPixelSize(static_cast<int>(font.pixelSize() * scale));
  QApplication::setFont(font);

  // High contrast: near-black backgrounds, white text, yellow selection (readable from the back of a room,
  // and distinguishable without colour vision).
  QPalette p;
  const QColor background(16, 16, 16), base(0, 0, 0), text(255, 255, 255), accent(255, 214, 0);
  p.setColor(QPalette::Window, background);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, base);
  p.setColor(QPalette::AlternateBase, QColor(40, 40, 40));
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, QColor(48, 48, 48));
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::Highlight, accent);
  p.setColor(QPalette::HighlightedText, base);
  p.setColor(QPalette::ToolTipBase, base);
  p.setColor(QPalette::ToolTipText, text);
  p.setColor(QPalette::Link, accent);
  p.setColor(QPalette::PlaceholderText, QColor(200, 200, 200));
  p.setColor(QPalette::Disabled, QPalette::Text, QColor(150, 150, 150));
  p.setColor(QPalette::Disabled, QPalette::ButtonText, QColor(150, 150, 150));
  p.setColor(QPalette::Disabled, QPalette::WindowText, QColor(150, 150, 150));
  QApplication::setPalette(p);
}

void applyLook(const AppLook& look) {
  QApplication::setFont(look.font);
  QApplication::setPalette(look.palette);
}

}  // namespace rt::app
