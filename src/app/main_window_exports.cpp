// MainWindow: exports (the view, matrices, every figure of a lesson) and the progress strip they share with
// the computations.
#include <vtkRenderWindow.h>
#include <QApplication>
#include <QBuffer>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QStatusBar>
#include <QThread>

#include "app/exports.h"
#include "app/figure_export.h"
#include "app/lesson_session.h"
#include "app/main_window.h"
#include "app/progress_strip.h"
#include "app/render_lock.h"
#include "app/scene_view.h"
#include "app/wording.h"
#include "lesson/step_result.h"
#include "viz/vtk_render.h"
#include "viz/vtk_views.h"

#include <algorithm>
#include <stdexcept>

namespace rt::app {

namespace {

// One pane as the exported figure draws it, at `size`: the same offscreen window and scene view that
// exportSceneFigure writes, read back into memory.
QImage paneImage(const SceneView& view, const Mesh& mesh, QSize size) {
  viz::SceneViewOptions options = view.viewOptions();
  options.image.width = size.width();
  options.image.height = size.height();
  const std::lock_guard lock(renderMutex());
  auto window = viz::makeOffscreenWindow(options.image.width, options.image.height);
  viz::addSceneView(window, mesh, view.currentCamera(), view.viewData(), options);
  int width = 0, height = 0;
  const std::vector<unsigned char> rgb = viz::captureRgb(window, width, height);
  QImage image(width, height, QImage::Format_RGB888);
  // The window's rows come bottom first.
  const auto row = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y)
    std::copy_n(rgb.data() + static_cast<std::size_t>(height - 1 - y) * row, row, image.scanLine(y));
  return image;
}

// Both panes side by side, written as the path's extension says (a 3D view has no vector form: the SVG and
// the PDF hold the picture).
void writeSideBySide(const QImage& left, const QImage& right, const QString& path) {
  QImage both(left.width() + right.width(), std::max(left.height(), right.height()), QImage::Format_RGB888);
  both.fill(Qt::black);
  QPainter painter(&both);
  painter.drawImage(0, 0, left);
  painter.drawImage(left.width(), 0, right);
  painter.end();
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == "pdf") {
    QPdfWriter pdf(path);
    pdf.setResolution(96);
    pdf.setPageSize(QPageSize(QSizeF(both.width(), both.height()) * 72.0 / 96.0, QPageSize::Point));
    pdf.setPageMargins(QMarginsF());
    QPainter page(&pdf);
    page.drawImage(QRect(0, 0, both.width(), both.height()), both);
  } else if (suffix == "svg") {
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    both.save(&buffer, "PNG");
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
      throw std::runtime_error(path.toStdString() + ": cannot write the file");
    file.write(QString(R"(<svg xmlns="http://www.w3.org/2000/svg" width="%1" height="%2">)"
                       R"(<image width="%1" height="%2" href="data:image/png;base64,)")
                   .arg(both.width())
                   .arg(both.height())
                   .toUtf8() +
               png.toBase64() + "\"/></svg>\n");
  } else if (!both.save(path)) {
    throw std::runtime_error(path.toStdString() + ": cannot write the file");
  }
}

}  // namespace

QSize MainWindow::viewExportSize() const {
  if (compare_ && secondaryView_ && secondaryView_->isVisible())
    return {std::max(primaryView_->width() + secondaryView_->width(), 1280),
            std::max(primaryView_->height(), 480)};
  return {std::max(primaryView_->width(), 640), std::max(primaryView_->height(), 480)};
}

bool MainWindow::exportView(const QString& path, QSize size) {
  if (!result_ || !result_->mesh) {
    showError(tr("There is no view to export yet."));
    return false;
  }
  try {
    const bool bothPanes = compare_ && secondaryView_ && secondaryView_->isVisible() && result_->compared &&
                           result_->compared->mesh;
    const QSize whole = size.isEmpty() ? viewExportSize() : size;
    if (bothPanes) {
      // Compare mode: the two panes as one figure, each half of the size.
      const QSize half(whole.width() / 2, whole.height());
      writeSideBySide(paneImage(*primaryView_, *result_->mesh, half),
                      paneImage(*secondaryView_, *result_->compared->mesh, half), path);
      statusLabel_->setText(tr("Both panes written to %1").arg(path));
      return true;
    }
    viz::SceneViewOptions options = primaryView_->viewOptions();
    options.image.width = whole.width();
    options.image.height = whole.height();
    exportSceneFigure(*result_->mesh, primaryView_->currentCamera(), primaryView_->viewData(), options,
                      path.toStdString());
    statusLabel_->setText(tr("View written to %1").arg(path));
    return true;
  } catch (const std::exception& e) {
    showError(QString::fromStdString(e.what()));
    return false;
  }
}

bool MainWindow::exportMatrixFile(const QString& which, const QString& path) {
  if (!result_) {
    showError(tr("There is nothing to export yet."));
    return false;
  }
  try {
    exportMatrix(*result_, which.toStdString(), path.toStdString());
    statusLabel_->setText(tr("%1 written to %2").arg(which, path));
    return true;
  } catch (const std::exception& e) {
    showError(QString::fromStdString(e.what()));
    return false;
  }
}

bool MainWindow::exportStepFigures(const QString& folder, const QString& format, const QString& name) {
  const auto* stepResult =
      result_ ? static_cast<const lesson::StepResult*>(result_->stepResult.get()) : nullptr;
  if (mode_ != Mode::Lesson || !stepResult) {
    showError(tr("Open a lesson step first: its figures are exported."));
    return false;
  }
  try {
    const auto& lesson = library_->lessons()[static_cast<std::size_t>(lesson_)];
    // The figures as shown: with the reader's parameters.
    lesson::Step step = lesson.steps[static_cast<std::size_t>(step_)];
    step.parameters = parameters_;
    const auto files = app::exportStepFigures(lesson, step, *stepResult, folder.toStdString(),
                                              format.toStdString(), name.toStdString());
    if (files.empty()) {
      showError(tr("This step has no figure besides the 3D view (File > Export view writes that one)."));
      return false;
    }
    lastExported_.clear();
    for (const auto& f : files) lastExported_ << QString::fromStdString(f);
    statusLabel_->setText(
        tr("%1 written to %2").arg(counted(static_cast<long long>(files.size()), tr("figure")), folder));
    return true;
  } catch (const std::exception& e) {
    showError(QString::fromStdString(e.what()));
    return false;
  }
}

bool MainWindow::exportAllFigures(const QString& folder, QSize size) {
  if (mode_ != Mode::Lesson || lesson_ < 0) {
    showError(tr("Open a lesson first: its figures are written one per step."));
    return false;
  }
  if (busy() || figureExport_) {
    showError(tr("Wait for the current computation to finish (or cancel it) first."));
    return false;
  }
  lastError_.clear();
  figureExport_ = new LessonFigureExport(*library_, lesson_, folder, size, this);
  connect(figureExport_, &LessonFigureExport::progress, progress_, &ProgressStrip::setProgress);
  connect(figureExport_, &LessonFigureExport::finished, this, [this, folder](int written) {
    finishFigureExport(tr("%1 written to %2").arg(counted(written, tr("figure")), folder), true);
  });
  connect(figureExport_, &LessonFigureExport::cancelled, this, [this, folder] {
    finishFigureExport(tr("Figure export cancelled: the figures written so far are in %1").arg(folder), true);
  });
  connect(figureExport_, &LessonFigureExport::failed, this,
          [this](const QString& message) { finishFigureExport(message, false); });
  showProgressStrip(tr("Writing the figures"));
  figureExport_->start();
  if (!blocking_) return true;
  // Blocking (tests, scripted use): the window keeps processing events, including the figures' drawing.
  while (figureExport_) {
    QApplication::processEvents(QEventLoop::AllEvents, 50);
    QThread::msleep(2);
  }
  return lastError_.isEmpty();
}

void MainWindow::cancelFigureExport() {
  if (figureExport_) figureExport_->cancel();
}

void MainWindow::finishFigureExport(const QString& message, bool ok) {
  figureExport_->deleteLater();
  figureExport_ = nullptr;
  if (!busy()) hideProgressStrip();
  if (ok)
    statusLabel_->setText(message);
  else
    showError(message);
}

void MainWindow::showProgressStrip(const QString& what) {
  progress_->begin(what);  // it appears after half a second; then appeared() shows the status bar if hidden
}

void MainWindow::hideProgressStrip() {
  progress_->end();
  if (presenter_) statusBar()->hide();
}

}  // namespace rt::app
