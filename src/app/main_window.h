// The main window: the lesson text beside the step's views, the table of contents, the iteration player, the
// residual chart, the matrix view and the parameter controls. It owns no computation: the pipeline runs in a
// ComputationRunner and results arrive as PipelineResult.
#pragma once

#include <QMainWindow>
#include <memory>

#include "app/app_options.h"
#include "app/computation_runner.h"
#include "app/pipeline.h"

class QLabel;
class QProgressBar;
class QPushButton;
class QSplitter;

namespace rt::app {

class SceneView;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(const AppOptions& options, QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens what the options ask for (a lesson step, a scene, or the last position). False on error
  // (lastError()).
  bool start();
  // Opens a scene file (or the built-in Cornell box when `path` is empty) with default settings and solves
  // it.
  bool openScene(const QString& path);
  // Recomputes the current scene with `settings` (reusing F when only materials or the light changed).
  void recompute(const PipelineSettings& settings);
  void cancelComputation();
  // Blocks (processing events) until no computation runs; false on timeout.
  bool waitUntilIdle(int timeoutMs = 60000);
  // Computations run on the calling thread (screenshots, deterministic tests).
  void setBlockingComputations(bool blocking) { blocking_ = blocking; }

  const PipelineResult* result() const { return result_.get(); }
  SceneView* primaryView() const { return primaryView_; }
  SceneView* secondaryView() const { return secondaryView_; }
  const QString& lastError() const { return lastError_; }
  bool busy() const { return runner_->busy(); }

 signals:
  void resultShown();

 private:
  void buildUi();
  void buildMenus();
  void showResult(std::shared_ptr<const PipelineResult> result);
  void showError(const QString& message);
  void setBusy(bool busy);

  AppOptions options_;
  ComputationRunner* runner_ = nullptr;
  bool blocking_ = false;
  Scene scene_;
  PipelineSettings settings_;
  std::shared_ptr<const PipelineResult> result_;
  QString lastError_;

  SceneView* primaryView_ = nullptr;
  SceneView* secondaryView_ = nullptr;
  QSplitter* viewSplitter_ = nullptr;
  QLabel* statusLabel_ = nullptr;
  QProgressBar* progressBar_ = nullptr;
  QPushButton* cancelButton_ = nullptr;
};

}  // namespace rt::app
