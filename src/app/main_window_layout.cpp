// MainWindow: how the window lays itself out for the room it has. Presenter mode gives the screen to the text
// and the figures; a narrow window (a 1024 px projector) folds the contents list away so that the step's
// text keeps a readable width; the cover over views that show a previous step follows the views.
#include <QDockWidget>
#include <QLabel>
#include <QLayout>
#include <QMenuBar>
#include <QResizeEvent>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <algorithm>

#include "app/main_window.h"
#include "app/residual_chart.h"

namespace rt::app {
namespace {

// Below this width the contents list and the parameters together would leave the text a column of a few
// words a line (about 150 px at 1024 px): the list folds away (View > Contents brings it back).
constexpr int kNarrowWindow = 1280;
// The text's share of the centre in a narrow window, and at ordinary widths (as the window is built), in per
// cent (the views, or an exercise's answer fields, get the rest).
constexpr int kNarrowTextPercent = 45, kTextPercent = 30;

}  // namespace

void MainWindow::setPresenterMode(bool on) {
  if (presenter_ == on) return;
  presenter_ = on;
  {
    const QSignalBlocker block(presenterAction_);
    presenterAction_->setChecked(on);
  }
  if (on) {
    normalLook_ = currentLook();
    applyPresenterLook(normalLook_);
    menuBar()->hide();
    statusBar()->hide();
    contentsDock_->hide();
    parametersDock_->hide();
    showFullScreen();
  } else {
    applyLook(normalLook_);
    menuBar()->show();
    statusBar()->show();
    contentsDock_->show();
    parametersDock_->show();
    // The window's width is decided anew (it may come back narrow): fitToWidth folds the list again.
    widthFit_ = WidthFit::Unknown;
    showNormal();
    fitToWidth();
  }
  textZoom_ = 1.0;
  zoomText(0);
  chart_->setLargeFonts(on);
  // The main figure fills the screen in presenter mode when the step has one; the 3D view otherwise.
  if (!on) setLargeFigure(false);
}

void MainWindow::resizeEvent(QResizeEvent* event) {
  QMainWindow::resizeEvent(event);
  fitToWidth();
}

void MainWindow::fitToWidth() {
  const WidthFit fit = width() < kNarrowWindow ? WidthFit::Narrow : WidthFit::Wide;
  // Only on crossing the width: between two crossings the reader's own arrangement (the list shown again
  // from the View menu, a splitter moved) stays as the reader left it. A window that opens wide keeps the
  // proportions it was built with.
  if (presenter_ || !centre_ || fit == widthFit_) return;
  const bool opening = widthFit_ == WidthFit::Unknown;
  widthFit_ = fit;
  if (fit == WidthFit::Wide) {
    if (contentsFolded_) contentsDock_->show();
    contentsFolded_ = false;
    if (opening) return;
  } else {
    contentsFolded_ = contentsFolded_ || !contentsDock_->isHidden();
    contentsDock_->hide();
  }
  // The list's room goes to the centre, not to the parameters beside it.
  const int parametersWidth = parametersDock_->width();
  // Shared out once the window has laid out the docks anew (the centre's width changes with the list's).
  QTimer::singleShot(0, this, [this, fit, parametersWidth] {
    if (fit != widthFit_) return;
    if (fit == WidthFit::Narrow && !parametersDock_->isHidden())
      resizeDocks({parametersDock_}, {parametersWidth}, Qt::Horizontal);
    layout()->activate();  // the centre at its new width: the shares below are of that width
    const int room = std::max(0, centre_->width() - centre_->handleWidth());
    const int text = room * (fit == WidthFit::Narrow ? kNarrowTextPercent : kTextPercent) / 100;
    // The views and an exercise's answer fields alike: one of the two is shown.
    centre_->setSizes({text, room - text, room - text});
  });
}

void MainWindow::showStale(bool on) {
  if (!on || !result_ || viewsPane_->isHidden()) {
    staleCover_->hide();
    return;
  }
  staleCover_->setGeometry(QRect(viewsPane_->mapTo(this, QPoint(0, 0)), viewsPane_->size()));
  staleCover_->raise();
  staleCover_->show();
}

}  // namespace rt::app
