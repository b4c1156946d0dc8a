// MainWindow: showing a computed result: the views, the text, the replay, the chart, the matrix, the step's
// figures and the parameters it ran with.
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

QString sceneSummary(const PipelineResult& r) {
  QString md =
      QString("# %1\n\n").arg(QString::fromStdString(r.scene->name.empty() ? "Scene" : r.scene->name));
  md += QString("%1 on %2, meshed into **%3**.\n\n")
            .arg(counted(static_cast<long long>(r.scene->patches.size()), "patch", "patches"),
                 counted(static_cast<long long>(r.scene->surfaces.size()), "surface"),
                 counted(static_cast<long long>(r.mesh->size()), "element"));
  if (r.F)
    md += QString("Form factors: %1%2.\n\n")
              .arg(QString::fromStdString(r.formFactorStats.summary()))
              .arg(r.formFactorsReused ? " (reused: only materials or the light changed)" : "");
  if (!r.solverName.empty()) md += QString("Solver %1.\n\n").arg(solveSummary(r));
  if (r.B.rows() == static_cast<Eigen::Index>(r.mesh->size()) && r.B.rows() > 0) {
    // The numbers that follow the light: a doubled light doubles them.
    const Eigen::VectorXd areas = r.mesh->areas();
    const Eigen::VectorXd grey = r.B.rowwise().mean();
    md += QString(
              "Mean radiosity over the scene's %1 %2² of surface: **%3 W/m²**; the brightest element, the "
              "light included: %4 W/m².\n\n")
              .arg(areas.sum(), 0, 'g', 4)
              .arg(QString::fromStdString(r.scene->unit))
              .arg(areas.dot(grey) / areas.sum(), 0, 'g', 4)
              .arg(grey.maxCoeff(), 0, 'g', 4);
  }
  if (!r.note.empty()) md += QString("*%1*\n\n").arg(QString::fromStdString(r.note));
  for (const auto& w : r.scene->warnings) md += QString("- warning: %1\n").arg(QString::fromStdString(w));
  for (const auto& w : r.formFactorStats.warnings)
    md += QString("- warning: %1\n").arg(QString::fromStdString(w));
  md += "\nChange the parameters on the right; click an element to see its row of the form-factor matrix.\n";
  return md;
}

std::vector<double> residualsOf(const PipelineResult& r) {
  std::vector<double> out;
  for (const IterationRecord& record : r.history) out.push_back(record.residual);
  return out;
}

}  // namespace

void MainWindow::showResult(std::shared_ptr<const PipelineResult> result) {
  const bool newStep = newStepPending_ || !result_;
  newStepPending_ = false;
  showStale(false);
  if (newStep) keptExposure_ = 0;
  showingKept_ = false;
  showViewPane(true);
  const bool longStep = recordComputeTime();
  // The views still point at the previous mesh until they get the new one: keep it alive until then.
  const std::shared_ptr<const PipelineResult> previous = result_;
  result_ = std::move(result);
  if (!pendingKey_.isEmpty()) recent_.keep(pendingKey_, result_);
  const PipelineResult& r = *result_;
  auto stepResult = std::static_pointer_cast<const lesson::StepResult>(r.stepResult);
  const lesson::Step* step =
      mode_ == Mode::Lesson
          ? &library_->lessons()[static_cast<std::size_t>(lesson_)].steps[static_cast<std::size_t>(step_)]
          : nullptr;
  // A step of text only has nothing to draw: its text takes the whole width instead of an empty view.
  viewsPane_->setVisible(r.mesh && r.mesh->size() > 0);
  primaryView_->setMaterialView(r.materials);
  primaryView_->setScene(r.mesh.get(), r.B, r.camera, newStep,
                         stepResult && stepResult->B.rows() == r.B.rows() ? stepResult->corners : RgbField());
  if (newStep && pendingCamera_ && r.mesh) primaryView_->applyCamera(*pendingCamera_);
  if (newStep) pendingCamera_.reset();
  primaryView_->setCaption(QString::fromStdString(compare_               ? paneCaption(r, r.compared.get())
                                                  : r.solverName.empty() ? r.title
                                                                         : r.solverName));
  if (stepResult && !stepResult->highlighted.empty()) primaryView_->setHighlighted(stepResult->highlighted);
  primaryView_->setRaySegments(stepResult && stepResult->raytrace
                                   ? viz::rayTreeSegments(stepResult->raytrace->tree)
                                   : std::vector<viz::RaySegments>{});
  if (compare_ && r.compared) {
    secondaryView_->setMaterialView(r.compared->materials);
    secondaryView_->setScene(r.compared->mesh.get(), r.compared->B, r.camera, false);
    secondaryView_->syncCameraFrom(*primaryView_);
    secondaryView_->setCaption(QString::fromStdString(paneCaption(*r.compared, &r)));
  } else {
    secondaryView_->setScene(nullptr, {}, r.camera, false);  // it must not keep a mesh that is about to go
  }
  applyStepDisplay(step);
  // Steps about form factors (no solution to show) colour the scene by the row of F of their source element.
  const bool formFactorStage =
      step && stepResult && r.F && stepResult->B.rows() == 0 &&
      (step->stage == lesson::Stage::FormFactors || step->stage == lesson::Stage::Hemicube ||
       step->stage == lesson::Stage::Nusselt || step->stage == lesson::Stage::Rays ||
       step->stage == lesson::Stage::Exact);
  if (formFactorStage && stepResult->sourceElement >= 0 && stepResult->sourceElement < r.F->rows()) {
    const int source = stepResult->sourceElement;
    primaryView_->setScalarField(r.F->row(source).transpose(), "F[" + std::to_string(source) + ", j]");
    primaryView_->setHighlighted({source});
    primaryView_->setCaption(tr("Form factors from element %1").arg(source));
  } else {
    primaryView_->setScalarField(Eigen::VectorXd(), {});
  }

  // An exercise step: its question below the step's text, the answer fields under both.
  const bool exercise = step && stepResult && stepResult->exercise;
  exercise_->setExercise(
      exercise ? stepResult->exercise : std::nullopt,
      mode_ == Mode::Lesson
          ? QString("%1/%2")
                .arg(QString::fromStdString(library_->lessons()[static_cast<std::size_t>(lesson_)].id))
                .arg(step_)
          : QString());
  QString markdown = mode_ == Mode::Lesson ? QString::fromStdString(r.text) : sceneSummary(r);
  if (exercise) markdown += "\n\n" + QString::fromStdString(stepResult->exercise->statement);
  setStepMarkdown(markdown);
  std::vector<QString> names{QString::fromStdString(r.solverName)};
  std::vector<std::vector<double>> runs{residualsOf(r)};
  if (compare_ && r.compared && !r.compared->history.empty()) {
    names.push_back(QString::fromStdString(r.compared->solverName) + tr(" (right)"));
    runs.push_back(residualsOf(*r.compared));
  }
  // A single record (a direct solve) has no convergence to show.
  if (runs.front().size() <= 1) runs.clear(), names.clear();
  // A step that compares several runs itself (solvers, methods) shows all of its curves.
  if (stepResult && stepResult->runs.size() > 1 && !compare_) {
    names.clear();
    runs.clear();
    for (const auto& run : stepResult->runs) {
      names.push_back(QString::fromStdString(run.label));
      runs.push_back(run.residuals);
    }
  }
  chart_->setRuns(names, runs);
  // The player counts as the status line does, after the longer run when two are compared.
  const PipelineResult& longest =
      compare_ && r.compared && r.compared->history.size() > r.history.size() ? *r.compared : r;
  player_->setIterations(iterationNumbers(longest), iterationUnit(longest.solverName));
  pathPlayer_->setPath(stepResult ? stepResult->cameraPath : std::vector<Camera>{});
  matrix_->setMatrix(r.F);
  figures_->clear();
  if (step && stepResult) {
    try {
      const auto& lesson = library_->lessons()[static_cast<std::size_t>(lesson_)];
      // The figures are drawn with the reader's parameters (a matrix kind, a display key), as the step ran.
      lesson::Step shown = *step;
      shown.parameters = parameters_;
      // Drawn on the worker thread with the step; else (a blocking computation) drawn here.
      figures_->keep(pendingKey_, r.figures);
      if (figures_->showStep(lesson, shown, *stepResult, pendingKey_) > 0 && newStep)
        tabs_->setCurrentWidget(figures_);
    } catch (const std::exception& e) {
      showError(tr("The step's figures could not be drawn: %1").arg(e.what()));
    }
  }
  if (newStep && figures_->figureCount() == 0 && tabs_->currentWidget() == figures_)
    tabs_->setCurrentIndex(0);
  if (longStep && step) keepStepResult();

  if (newStep) {
    std::vector<std::pair<QString, Rgb>> surfaces;
    for (const Surface& s : r.scene->surfaces)
      surfaces.emplace_back(QString::fromStdString(s.name), r.scene->materials[s.material].reflectance);
    if (step) {
      // A value the step does not let the reader change shows what the step used: a hemicube or exact step
      // computes with its own form-factor method, a step comparing solvers replays one of them, whatever the
      // defaults say.
      lesson::StepParameters shown = parameters_;
      const auto offered = [&](const char* key) {
        return std::find(step->controls.begin(), step->controls.end(), key) != step->controls.end();
      };
      if (!offered("method") && !r.formFactorMethod.empty()) shown.method = r.formFactorMethod;
      if (!offered("solver") && !r.solverName.empty() && r.solverName != "bounces")
        shown.solver = r.solverName;
      panel_->setStep(shown, step->controls, false, surfaces);
    } else {
      panel_->setStep(parameters_, {}, true, surfaces);
    }
  }

  if (!r.mesh || r.mesh->size() == 0) {
    const bool choice = exercise && !stepResult->exercise->questions.front().choices.empty();
    statusLabel_->setText(choice     ? tr("A question: pick one answer, then Check")
                          : exercise ? tr("An exercise: type the answers, then Check (or Enter in a field)")
                                     : tr("A step of text: Right or Page Down for the next step"));
    emit resultShown();
    if (newStep) QTimer::singleShot(0, this, &MainWindow::prefetchNextStep);
    return;
  }
  QString status = counted(static_cast<long long>(r.mesh->size()), tr("element"));
  if (!r.solverName.empty()) status += ", " + solveSummary(r);
  if (r.formFactorsReused) status += tr(", form factors reused");
  if (!r.materials && parameters_.exposure <= 0 && keptExposure_ > 0)
    status += tr(", exposure %1 (automatic, kept for this step)").arg(keptExposure_, 0, 'g', 3);
  if (!r.note.empty()) status += " (" + QString::fromStdString(r.note) + ")";
  statusLabel_->setText(status);
  emit resultShown();
  if (newStep) QTimer::singleShot(0, this, &MainWindow::prefetchNextStep);
}

}  // namespace rt::app
