// The main window: the table of contents, the step's text beside its views, the iteration player and residual
// chart, the form-factor matrix, the parameter controls and compare mode. It owns no computation: steps and
// scenes are computed by a ComputationRunner on a worker thread and arrive as PipelineResult.
#pragma once

#include <QFont>
#include <QMainWindow>
#include <QVariantMap>
#include <memory>
#include <optional>

#include "app/app_options.h"
#include "app/camera_views.h"
#include "app/compare_choice.h"
#include "app/computation_runner.h"
#include "app/keys_dialog.h"
#include "app/lesson_text_view.h"
#include "app/pipeline.h"
#include "app/presenter_style.h"
#include "app/recent_results.h"
#include "app/step_result_cache.h"
#include "lesson/lesson.h"

class QAction;
class QCheckBox;
class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QPushButton;
class QSplitter;
class QTabWidget;

namespace rt::app {

class ContentsTree;
class ExercisePanel;
class FiguresPane;
class IterationPlayer;
class CameraPathPlayer;
class LessonFigureExport;
class LessonLibrary;
class MatrixView;
class ParameterHistory;
class ParameterPanel;
class ProgressStrip;
class ResidualChart;
class SceneView;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  // `library` null: lessons from lesson::defaultFolders().
  explicit MainWindow(const AppOptions& options, std::unique_ptr<LessonLibrary> library = nullptr,
                      QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens what the options ask for: a scene, a lesson step, the remembered position, or the welcome lesson.
  // False on error (lastError()).
  bool start();
  // A lesson by id at a 0-based step; false (lastError()) when there is no such lesson or step.
  bool openLesson(const QString& id, int step = 0);
  bool openStep(int lessonIndex, int step);
  bool nextStep();
  bool previousStep();
  // Opens a scene file (empty: the built-in Cornell box) and solves it with every control enabled.
  bool openScene(const QString& path);

  // Recomputes the current step or scene with changed parameters (F is reused when only light/materials
  // changed).
  void applyParameters(const lesson::StepParameters& parameters);
  void cancelComputation();
  // Blocks (processing events) until no computation runs; false on timeout.
  bool waitUntilIdle(int timeoutMs = 120000);
  // Whether the next step is being computed ahead while the reader reads this one (prefetchNextStep), and
  // blocking until it is done, as a reader who reads the step before turning the page.
  bool prefetching() const;
  bool waitUntilPrefetched(int timeoutMs = 120000);
  // Computations run on the calling thread (screenshots, deterministic tests).
  void setBlockingComputations(bool blocking) { blocking_ = blocking; }

  void setCompareMode(bool on);
  bool compareMode() const { return compare_; }
  // What the right pane changes (empty members: the left pane's); set from the compare controls.
  CompareChoice compareChoice() const;
  void setCompareChoice(const CompareChoice& choice);
  void setPresenterMode(bool on);
  bool presenterMode() const { return presenter_; }
  // A restored session's long step shows what it showed last time, kept on disk, until the reader computes
  // it.
  bool showingKeptResult() const { return showingKept_; }

  // Exports (errors go to lastError() and a message box when visible; false then).
  // `size` empty: viewExportSize(). In compare mode both panes make one figure of that size, side by side.
  bool exportView(const QString& path, QSize size = QSize());
  // The size File > Export view proposes: the view's on screen (both panes in compare mode), at least
  // 640 x 480 (1280 x 480 for two panes).
  QSize viewExportSize() const;
  bool exportMatrixFile(const QString& which, const QString& path);  // which: F, K or B
  // Computes every step on the worker side and draws its figures, with progress and cancel; returns at once
  // (true: started) unless computations are blocking, in which case it returns when the figures are written.
  bool exportAllFigures(const QString& folder, QSize size = QSize(1200, 900));
  bool exportingFigures() const { return figureExport_ != nullptr; }
  void cancelFigureExport();
  // The current step's figures other than the 3D view, drawn as the book draws them, into `folder` as
  // `format` ("svg", "pdf": vectors; "png") and named `name` (empty: the step's `figure:`); false
  // (lastError()) when the step has none.
  bool exportStepFigures(const QString& folder, const QString& format, const QString& name = QString());
  // The files the last exportStepFigures wrote.
  const QStringList& lastExportedFiles() const { return lastExported_; }
  // "cornell-box-3-view.png": what a save dialog proposes for `what` of the current step or scene.
  QString suggestedFileName(const QString& what, const QString& extension) const;

  // Presenter mode's text size: `steps` up (positive) or down; each step is 10 %.
  void zoomText(int steps);
  // The step's figures fill the main pane instead of the 3D view (View > Step figure in the main pane).
  void setLargeFigure(bool on);
  bool largeFigure() const { return largeFigure_; }
  // The camera of the step or scene, or a standard view of its bounding box.
  void resetView();
  void showStandardView(StandardView view);
  // Computes the shown step now (a step the restored session did not compute on its own).
  void computeNow();
  bool computationDeferred() const { return deferred_; }
  // The recently opened scene files, newest first (File > Open recent).
  QStringList recentFiles() const;
  // Every key of the window (Help > Keys).
  std::vector<KeyBinding> keyBindings();
  void showKeys();
  ParameterHistory* history() const { return history_; }

  // State for tests and the status bar.
  const PipelineResult* result() const { return result_.get(); }
  int currentLesson() const { return lesson_; }
  int currentStep() const { return step_; }
  LessonLibrary* library() const { return library_.get(); }
  const QString& lastError() const { return lastError_; }
  bool busy() const;
  SceneView* primaryView() const { return primaryView_; }
  SceneView* secondaryView() const { return secondaryView_; }
  LessonTextView* textView() const { return text_; }
  ExercisePanel* exercisePanel() const { return exercise_; }
  IterationPlayer* player() const { return player_; }
  CameraPathPlayer* pathPlayer() const { return pathPlayer_; }
  ResidualChart* residualChart() const { return chart_; }
  MatrixView* matrixView() const { return matrix_; }
  ParameterPanel* parameterPanel() const { return panel_; }
  ContentsTree* contents() const { return contents_; }
  FiguresPane* figuresPane() const { return figures_; }
  bool viewsShown() const;
  ProgressStrip* progressStrip() const { return progress_; }

 signals:
  void resultShown();

 protected:
  void closeEvent(QCloseEvent* event) override;
  // The step's text gives the window's keys back: Left, Right, Page Up/Down and Space step and play even
  // after the reader clicked into the text (whose invisible caret would otherwise take them).
  bool eventFilter(QObject* watched, QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  enum class Mode { None, Lesson, Scene };
  void buildUi();
  void buildMenus();
  void addRecentFile(const QString& path);
  void rebuildRecentMenu();
  // The reader's parameters back from the undo history: shown in the panel and computed.
  void restoreParameters(const lesson::StepParameters& parameters);
  // The session (position, parameters, scene, camera) written at every change and read by start().
  void saveSession();
  // The step's text; its equations (code blocks, set in a fixed font of their own size) at the text's size.
  void setStepMarkdown(const QString& markdown);
  // The 3D view and the iteration player (hidden while a kept result without a solution is shown).
  void showViewPane(bool shown);
  bool restoreSession();
  bool isLongStep(int lessonIndex, int step) const;
  // The restored session's parameters, over the step's or scene's own (once, by openStep / openScene).
  void applySessionParameters();
  // How long the shown step took, so that a restored session knows a long one. Returns whether the step
  // counts as long (a benchmark, or long this time or the last time).
  bool recordComputeTime();
  // A long step's text and figures, kept for a restored session (StepResultCache).
  void keepStepResult();
  // A restored session's long step: what it showed last time, if kept with the same parameters.
  bool showKeptResult();
  // The current lesson step, the reader's values of its controls and the compare pane's choice, as one key.
  QString recentKey() const;
  QString recentKey(int lessonIndex, int step, const lesson::StepParameters& parameters) const;
  // While the reader reads a step, the next one is computed on the worker side and its figures drawn, so
  // that Page Down shows it from memory (recent_, the figures pane's drawn figures). Not for exercises and
  // text (instant anyway), benchmarks and steps that took long last time (the reader starts those), compare
  // mode, or blocking computations.
  void prefetchNextStep();
  void keepPrefetched(std::shared_ptr<const PipelineResult> result);
  // Covers the views while a new step computes, so that the previous step's pictures look out of date.
  void showStale(bool on);
  // Lays the window out for its width: below a projector's width the contents list folds away and the text
  // gets a readable share of the centre; back above it, both return.
  void fitToWidth();
  void requestComputation();
  void showResult(std::shared_ptr<const PipelineResult> result);
  void showIteration(int index);
  void selectElements(int first, int second);
  void showError(const QString& message);
  void showProgressStrip(const QString& what);
  void hideProgressStrip();
  void finishFigureExport(const QString& message, bool ok);
  void setBusy(bool busy);
  void updateNavigation();
  void rememberPosition();
  void applyStepDisplay(const lesson::Step* step);  // from parameters_
  // With `size`, the dialog also asks for the picture's width and height in pixels, starting from *size.
  QString exportFileDialog(const QString& title, const QString& filters, const QString& suggested,
                           QSize* size = nullptr);

  AppOptions options_;
  std::unique_ptr<LessonLibrary> library_;
  ComputationRunner* runner_ = nullptr;
  ComputationRunner* prefetch_ = nullptr;  // the next step, computed ahead (prefetchNextStep)
  // What prefetch_ computes: the step, under its recent key, and the step the reader was on then.
  struct Prefetched {
    QString key;
    int lesson = -1, step = -1, afterLesson = -1, afterStep = -1;
  };
  Prefetched prefetched_;
  bool blocking_ = false;
  Mode mode_ = Mode::None;
  int lesson_ = -1;
  int step_ = -1;
  lesson::StepParameters parameters_;
  bool newStepPending_ = false;
  bool deferred_ = false;                // a long step of the restored session, waiting for Compute
  std::optional<Camera> pendingCamera_;  // the restored session's camera, for the first result
  QVariantMap sessionParameters_;        // the restored session's parameters, for the first step
  QString scenePath_;                    // the reader's scene file (empty: the built-in box)
  qint64 computeStartedMs_ = 0;
  ParameterHistory* history_ = nullptr;
  bool largeFigure_ = false;
  QFont normalTextFont_;
  double textZoom_ = 1.0;
  Scene scene_;
  std::shared_ptr<const PipelineResult> result_;
  // The reader's own scene: its pipeline keeps form factors between runs (a change of material re-solves).
  std::shared_ptr<Pipeline> scenePipeline_ = std::make_shared<Pipeline>();
  QString lastError_;
  QStringList lastExported_;
  bool compare_ = false;
  bool presenter_ = false;
  // Whether the window is laid out as narrower than the contents list, the parameters and a readable text
  // need (fitToWidth; unknown until the first fit), and whether the list was folded away for it (to come back
  // when the window is wide again).
  enum class WidthFit { Unknown, Wide, Narrow };
  WidthFit widthFit_ = WidthFit::Unknown;
  bool contentsFolded_ = false;
  AppLook normalLook_;

  ContentsTree* contents_ = nullptr;
  LessonTextView* text_ = nullptr;
  ExercisePanel* exercise_ = nullptr;  // the answer fields of an exercise step
  QString stepMarkdown_;               // the step's text, without an exercise's hint or solution under it
  QLabel* stepLabel_ = nullptr;
  QPushButton* backButton_ = nullptr;
  QPushButton* nextButton_ = nullptr;
  SceneView* primaryView_ = nullptr;
  SceneView* secondaryView_ = nullptr;
  QSplitter* viewSplitter_ = nullptr;
  QSplitter* centre_ = nullptr;  // the text | the views | an exercise's answer fields
  QWidget* viewsPane_ = nullptr;
  QLabel* staleCover_ = nullptr;  // over viewsPane_ while a new step computes (showStale)  // views, player
                                  // and tabs: hidden for a step of text only
  IterationPlayer* player_ = nullptr;
  CameraPathPlayer* pathPlayer_ = nullptr;  // a step's camera path: the walkthrough after one solve
  ResidualChart* chart_ = nullptr;
  MatrixView* matrix_ = nullptr;
  FiguresPane* figures_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  ParameterPanel* panel_ = nullptr;
  QCheckBox* compareBox_ = nullptr;
  QComboBox* compareSolver_ = nullptr;
  QComboBox* compareMethod_ = nullptr;
  QComboBox* compareMesh_ = nullptr;
  QDockWidget* contentsDock_ = nullptr;
  QDockWidget* parametersDock_ = nullptr;
  QAction* presenterAction_ = nullptr;
  QAction* compareAction_ = nullptr;
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  QAction* computeAction_ = nullptr;
  QAction* largeFigureAction_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QPushButton* computeButton_ = nullptr;
  StepResultCache stepCache_;
  // The steps seen last, by recentKey(): a step revisited with the same settings is shown from memory.
  RecentResults recent_;
  QString pendingKey_;
  // The automatic exposure of the step's (or scene's) first result, kept while the reader changes only the
  // light or the reflectances, so that a brighter light shows as a brighter room; 0 until a result is shown.
  double keptExposure_ = 0;  // the key of the computation under way (empty: a scene, not kept)
  bool showingKept_ = false;
  QLabel* statusLabel_ = nullptr;
  ProgressStrip* progress_ = nullptr;
  LessonFigureExport* figureExport_ = nullptr;
};

}  // namespace rt::app
