// MainWindow: opening lessons, steps and scenes, and computing them (on the worker thread, or from
// memory for a step seen a moment ago).
#include <QApplication>
#include <QComboBox>
#include <QDateTime>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QTabWidget>
#include <QThread>
#include <QTimer>
#include <algorithm>

#include "app/builtin_scene.h"
#include "app/camera_path_player.h"
#include "app/contents_tree.h"
#include "app/exercise_panel.h"
#include "app/figures_pane.h"
#include "app/iteration_player.h"
#include "app/lesson_session.h"
#include "app/main_window.h"
#include "app/matrix_view.h"
#include "app/parameter_history.h"
#include "app/parameter_panel.h"
#include "app/residual_chart.h"
#include "app/scene_settings.h"
#include "app/scene_view.h"
#include "app/step_figures.h"
#include "app/wording.h"
#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/solvers/solver.h"
#include "lesson/step_result.h"
#include "lesson/step_settings.h"

namespace rt::app {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace

bool MainWindow::start() {
  const CompareChoice choice{options_.compareSolver.toStdString(), options_.compareMethod.toStdString(),
                             options_.compareMesh.toStdString()};
  setCompareChoice(choice);
  const CompareChoice applied = compareChoice();
  if (applied.solver != choice.solver || applied.method != choice.method || applied.mesh != choice.mesh) {
    lastError_ = tr("unknown --compare-solver or --compare-method (solvers: %1; methods: %2)")
                     .arg(QString::fromStdString(joined(solverNames())),
                          QString::fromStdString(joined(formFactorMethodNames())));
    return false;
  }
  if (options_.compare) setCompareMode(true);
  if (options_.presenter) setPresenterMode(true);
  if (!options_.scene.isEmpty()) return openScene(options_.scene);
  if (!options_.lesson.isEmpty()) return openLesson(options_.lesson, std::max(0, options_.step - 1));
  if (options_.step > 0) {
    lastError_ = tr("--step needs --lesson");
    return false;
  }
  if (restoreSession()) return true;
  if (library_->welcomeIndex() >= 0) return openStep(library_->welcomeIndex(), 0);
  return openScene(QString());  // no lessons at all: the built-in Cornell box
}

bool MainWindow::openLesson(const QString& id, int step) {
  const int index = library_->indexOf(id.toStdString());
  if (index < 0) {
    QString known;
    for (const auto& l : library_->lessons())
      known += (known.isEmpty() ? "" : ", ") + QString::fromStdString(l.id);
    QString message = tr("no lesson '%1' in %2 (known: %3)")
                          .arg(id, QString::fromStdString(library_->folders().lessons), known);
    for (const auto& e : library_->errors()) message += "\n" + QString::fromStdString(e);
    showError(message);
    return false;
  }
  return openStep(index, step);
}

bool MainWindow::openStep(int lessonIndex, int step) {
  const auto& lessons = library_->lessons();
  if (lessonIndex < 0 || lessonIndex >= static_cast<int>(lessons.size())) return false;
  const lesson::Lesson& lesson = lessons[static_cast<std::size_t>(lessonIndex)];
  if (step < 0 || step >= static_cast<int>(lesson.steps.size())) {
    showError(tr("lesson '%1' has %2: there is no step %3")
                  .arg(QString::fromStdString(lesson.id),
                       counted(static_cast<long long>(lesson.steps.size()), tr("step")))
                  .arg(step + 1));
    return false;
  }
  mode_ = Mode::Lesson;
  lesson_ = lessonIndex;
  step_ = step;
  const lesson::Step& s = lesson.steps[static_cast<std::size_t>(step)];
  parameters_ = s.parameters;
  applySessionParameters();
  history_->clear();
  newStepPending_ = true;
  setWindowTitle(tr("%1 - Radiosity Textbook").arg(lessonHeading(lesson)));
  contents_->setCurrent(lessonIndex, step);
  updateNavigation();
  rememberPosition();
  const bool defer = deferred_;
  computeButton_->setVisible(defer);
  showingKept_ = false;
  showViewPane(true);
  // The panel shows the step's own controls and values at once (not the previous step's while this one
  // computes); the scene's surfaces come with the result.
  panel_->setStep(parameters_, s.controls, false, {});
  if (defer && showKeptResult()) return true;
  if (defer) {
    // A long step of the restored session: the reader starts it.
    setStepMarkdown(tr("## %1\n\n*This step takes a while to compute (%2). It was not started on its own: "
                       "press **Compute this step** below, or F5, when you want its results.*\n\n%3")
                        .arg(QString::fromStdString(s.title),
                             s.stage == lesson::Stage::Benchmark ? tr("it measures every method")
                                                                 : tr("it took long last time"),
                             QString::fromStdString(s.text)));
    statusLabel_->setText(tr("Not computed yet: Go > Compute this step (F5)"));
    return true;
  }
  // The text appears at once; numbers quoted from the result are filled in when it arrives.
  setStepMarkdown(QString("## %1\n\n*Computing...*").arg(QString::fromStdString(s.title)));
  requestComputation();
  return true;
}

bool MainWindow::nextStep() {
  if (mode_ != Mode::Lesson) return false;
  const auto& lessons = library_->lessons();
  if (step_ + 1 < static_cast<int>(lessons[static_cast<std::size_t>(lesson_)].steps.size()))
    return openStep(lesson_, step_ + 1);
  if (lesson_ + 1 < static_cast<int>(lessons.size())) return openStep(lesson_ + 1, 0);
  return false;
}

bool MainWindow::previousStep() {
  if (mode_ != Mode::Lesson) return false;
  if (step_ > 0) return openStep(lesson_, step_ - 1);
  if (lesson_ > 0) {
    const auto& previous = library_->lessons()[static_cast<std::size_t>(lesson_ - 1)];
    return openStep(lesson_ - 1, static_cast<int>(previous.steps.size()) - 1);
  }
  return false;
}

bool MainWindow::openScene(const QString& path) {
  try {
    scene_ = path.isEmpty() ? builtinCornellBox() : loadScene(path.toStdString());
  } catch (const std::exception& e) {
    showError(QString::fromStdString(e.what()));
    return false;
  }
  mode_ = Mode::Scene;
  lesson_ = step_ = -1;
  parameters_ = lesson::StepParameters{};  // the default form-factor method among them
  chooseSceneSolve(scene_.patches.size(), parameters_);
  applySessionParameters();
  history_->clear();
  deferred_ = false;
  computeButton_->hide();
  scenePath_ = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
  if (!path.isEmpty()) addRecentFile(path);
  newStepPending_ = true;
  result_.reset();
  setWindowTitle(tr("%1 - Radiosity Textbook").arg(QString::fromStdString(scene_.name)));
  setStepMarkdown(QString("# %1\n\n*Computing...*").arg(QString::fromStdString(scene_.name)));
  updateNavigation();
  requestComputation();
  return true;
}

void MainWindow::applyParameters(const lesson::StepParameters& parameters) {
  if (mode_ == Mode::None) return;
  history_->recordChange(parameters_, parameters);
  const bool recolourOnly =
      mode_ == Mode::Scene && result_ && !busy() && changesOnlyDisplay(parameters_, parameters);
  // A new mesh, method or solver is a new picture, exposed anew; a changed light is shown in the same one.
  if (!changesOnlyLightOrDisplay(parameters_, parameters)) keptExposure_ = 0;
  parameters_ = parameters;
  saveSession();
  // A scene's solution does not depend on how it is shown: the views recolour it (a lesson step's figures
  // and text may, so a step computes again).
  if (recolourOnly)
    applyStepDisplay(nullptr);
  else
    requestComputation();
}

void MainWindow::requestComputation() {
  lastError_.clear();
  // What the reader asks for now comes first: the step computed ahead stops at its next progress check.
  if (prefetch_) prefetch_->cancel();
  computeStartedMs_ = QDateTime::currentMSecsSinceEpoch();
  const bool compare = compare_;
  const CompareChoice choice = compare ? compareChoice() : CompareChoice{};
  ComputationRunner::Job job;
  pendingKey_.clear();
  if (mode_ == Mode::Lesson) pendingKey_ = recentKey();
  if (const auto kept = pendingKey_.isEmpty() ? nullptr : recent_.find(pendingKey_)) {
    // Through the runner all the same: it cancels a computation under way, whose result must not follow.
    job = [kept](Progress&) { return *kept; };
  } else if (mode_ == Mode::Lesson) {
    LessonLibrary* library = library_.get();
    const int l = lesson_, s = step_;
    const lesson::StepParameters parameters = parameters_;
    const QString folder = figures_->newFolder();
    const QSize size = figures_->drawSize();
    job = [library, l, s, parameters, compare, choice, folder, size](Progress& progress) {
      PipelineResult result = library->runStep(l, s, parameters, choice, progress);
      // Compare mode with nothing chosen still fills the right pane (the same result), so both panes show.
      if (compare && !result.compared) result.compared = std::make_shared<PipelineResult>(result);
      const lesson::Lesson& lesson = library->lessons()[static_cast<std::size_t>(l)];
      addStepFigures(result, lesson, lesson.steps[static_cast<std::size_t>(s)], parameters, folder, size,
                     progress);
      return result;
    };
  } else if (mode_ == Mode::Scene) {
    const Scene scene = scene_;
    const PipelineSettings settings = lesson::settingsFor(parameters_, parameters_.method);
    std::shared_ptr<Pipeline> pipeline = scenePipeline_;
    job = [scene, settings, pipeline, compare, choice](Progress& progress) {
      PipelineResult result = runScenePipeline(*pipeline, scene, settings, progress);
      if (!compare) return result;
      if (!choice.changesSomething()) {
        result.compared = std::make_shared<PipelineResult>(result);
        return result;
      }
      if (choice.refinesMesh()) {
        result.compared = std::make_shared<PipelineResult>(
            runRefinedPipeline(result.scene, choice.mesh, /*quick=*/false, progress));
        return result;
      }
      PipelineSettings other = settings;
      if (!choice.solver.empty()) other.solver = choice.solver;
      if (!choice.method.empty()) other.method = choice.method;
      other.mesh = scaledMesh(other.mesh, choice.mesh);
      result.compared = std::make_shared<PipelineResult>(runScenePipeline(*pipeline, scene, other, progress));
      return result;
    };
  } else {
    return;
  }
  // An exercise or a page of text is computed in an instant: it never waits behind another step's long
  // computation (which it cancels), nor shows that step's view while it would.
  const auto stage = [this] {
    return library_->lessons()[static_cast<std::size_t>(lesson_)]
        .steps[static_cast<std::size_t>(step_)]
        .stage;
  };
  const bool instant =
      mode_ == Mode::Lesson && (stage() == lesson::Stage::Exercise || stage() == lesson::Stage::Text);
  if (blocking_)
    runner_->runBlocking(job);
  else if (instant)
    runner_->runNow(job);
  else {
    showStale(true);
    runner_->start(std::move(job));
  }
}

void MainWindow::cancelComputation() {
  if (runner_) runner_->cancel();
}

bool MainWindow::waitUntilIdle(int timeoutMs) {
  QElapsedTimer timer;
  timer.start();
  while (runner_->busy()) {
    if (timer.elapsed() > timeoutMs) return false;
    QApplication::processEvents(QEventLoop::AllEvents, 50);
    QThread::msleep(2);
  }
  QApplication::processEvents();
  return true;
}

}  // namespace rt::app
