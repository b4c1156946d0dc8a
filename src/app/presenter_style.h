// Presenter mode's look: large fonts and a high-contrast palette for a projector, and a way back to the
// normal look.
#pragma once

#include <QFont>
#include <QPalette>

namespace rt::app {

struct AppLook {
  QFont font;
  QPalette palette;
};

// The application's current font and palette (to restore them later).
AppLook currentLook();
// Fonts `scale` times larger, white on near-black text areas, yellow selection.
void applyPresenterLook(const AppLook& normal, double scale = 1.6);
void applyLook(const AppLook& look);

}  // namespace rt::app
