#include "app/main_window.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QStatusBar>
#include <QThread>

#include "app/builtin_scene.h"
#include "app/scene_view.h"
#include "core/io/scene_loader.h"

namespace rt::app {

MainWindow::MainWindow(const AppOptions& options, QWidget* parent) : QMainWindow(parent), options_(options) {
  setWindowTitle("Radiosity Textbook");
  runner_ = new ComputationRunner(this);
  connect(runner_, &ComputationRunner::finished, this, &MainWindow::showResult);
  connect(runner_, &ComputationRunner::failed, this, &MainWindow::showError);
  connect(runner_, &ComputationRunner::cancelled, this,
          [this] { statusLabel_->setText("Cancelled: the previous result is still shown."); });
  connect(runner_, &ComputationRunner::busyChanged, this, &MainWindow::setBusy);
  connect(runner_, &ComputationRunner::progress, this, [this](double fraction, const QString& stage) {
    progressBar_->setValue(static_cast<int>(fraction * 1000));
    progressBar_->setFormat(stage + "  %p%");
  });
  buildUi();
  buildMenus();
  resize(options.size);
}

MainWindow::~MainWindow() = default;

void MainWindow::buildUi() {
  viewSplitter_ = new QSplitter(Qt::Horizontal, this);
  primaryView_ = new SceneView(viewSplitter_);
  secondaryView_ = new SceneView(viewSplitter_);
  secondaryView_->hide();
  viewSplitter_->addWidget(primaryView_);
  viewSplitter_->addWidget(secondaryView_);
  setCentralWidget(viewSplitter_);

  statusLabel_ = new QLabel(this);
  progressBar_ = new QProgressBar(this);
  progressBar_->setRange(0, 1000);
  progressBar_->setMaximumWidth(320);
  progressBar_->hide();
  cancelButton_ = new QPushButton(tr("Cancel"), this);
  cancelButton_->hide();
  connect(cancelButton_, &QPushButton::clicked, this, &MainWindow::cancelComputation);
  statusBar()->addWidget(statusLabel_, 1);
  statusBar()->addPermanentWidget(progressBar_);
  statusBar()->addPermanentWidget(cancelButton_);
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open scene..."), QKeySequence::Open, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open scene"), QString(),
                                                      tr("Scenes (*.json *.obj);;All files (*)"));
    if (!path.isEmpty()) openScene(path);
  });
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
}

bool MainWindow::start() {
  if (!options_.scene.isEmpty()) return openScene(options_.scene);
  return openScene(QString());
}

bool MainWindow::openScene(const QString& path) {
  try {
    scene_ = path.isEmpty() ? builtinCornellBox() : loadScene(path.toStdString());
  } catch (const std::exception& e) {
    showError(QString::fromStdString(e.what()));
    return false;
  }
  settings_ = PipelineSettings{};
  settings_.mesh.mode = MeshOptions::Mode::Count;
  settings_.mesh.count = 4;
  result_.reset();
  primaryView_->setMesh(nullptr, {}, false);
  recompute(settings_);
  return true;
}

void MainWindow::recompute(const PipelineSettings& settings) {
  settings_ = settings;
  lastError_.clear();
  if (blocking_)
    runner_->runBlocking(scene_, settings_, result_.get());
  else
    runner_->start(scene_, settings_, result_.get());
}

void MainWindow::cancelComputation() {
  runner_->cancel();
}

bool MainWindow::waitUntilIdle(int timeoutMs) {
  QElapsedTimer timer;
  timer.start();
  while (runner_->busy()) {
    if (timer.elapsed() > timeoutMs) return false;
    QApplication::processEvents(QEventLoop::AllEvents, 50);
    QThread::msleep(5);
  }
  QApplication::processEvents();
  return true;
}

void MainWindow::showResult(std::shared_ptr<const PipelineResult> result) {
  const bool newMesh = !result_ || result_->mesh->geometryHash() != result->mesh->geometryHash();
  result_ = std::move(result);
  const Camera camera = result_->scene->cameraOrDefault();
  primaryView_->setRadiosity(result_->B);
  primaryView_->setMesh(result_->mesh.get(), camera, newMesh);
  QString text =
      QString("%1: %2 elements").arg(QString::fromStdString(result_->scene->name)).arg(result_->mesh->size());
  if (!result_->solverName.empty())
    text += QString(", %1: %2 after %3 iterations, residual %4")
                .arg(QString::fromStdString(result_->solverName),
                     QString::fromStdString(toString(result_->status)))
                .arg(result_->iterations)
                .arg(result_->residual, 0, 'g', 3);
  if (result_->formFactorsReused) text += ", form factors reused";
  if (!result_->note.empty()) text += " (" + QString::fromStdString(result_->note) + ")";
  statusLabel_->setText(text);
  emit resultShown();
}

void MainWindow::showError(const QString& message) {
  lastError_ = message;
  statusLabel_->setText(tr("Error: %1").arg(message));
  if (options_.screenshot.isEmpty() && isVisible())
    QMessageBox::warning(this, tr("Radiosity Textbook"), message);
}

void MainWindow::setBusy(bool busy) {
  progressBar_->setVisible(busy);
  cancelButton_->setVisible(busy);
  if (busy) progressBar_->setValue(0);
}

}  // namespace rt::app
