// MainWindow: the session kept between runs (lesson and step or scene file, the reader's parameters, the
// camera), the steps a restored session leaves for the reader to start, undo's way back into the panel, the
// view commands (text size, the large figure, reset and standard views), and what follows the reader's
// position: the iteration shown, the selected elements, the navigation under the text.
#include <QDateTime>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QTabWidget>

#include "app/contents_tree.h"
#include "app/figures_pane.h"
#include "app/iteration_player.h"
#include "app/lesson_session.h"
#include "app/main_window.h"
#include "app/matrix_view.h"
#include "app/parameter_history.h"
#include "app/parameter_panel.h"
#include "app/residual_chart.h"
#include "app/scene_view.h"
#include "lesson/step_keys.h"
#include "viz/display_pipeline.h"

namespace rt::app {
namespace {

// A step that took longer than this is not recomputed on its own when a session is restored.
constexpr qint64 kLongStepMs = 5000;

QString stepKey(const std::string& lesson, int step) {
  return QString("timing/%1/%2").arg(QString::fromStdString(lesson)).arg(step);
}

QVariantMap parameterMap(const lesson::StepParameters& p) {
  QVariantMap map;
  for (const lesson::StepKey& key : lesson::stepKeyTable()) {
    if (!key.control) continue;
    if (key.name == "reflectance") {
      for (const auto& [surface, rho] : p.reflectance) {
        const std::string name = "reflectance." + surface;
        if (auto text = lesson::stepValueText(p, key, name))
          map[QString::fromStdString(name)] = QString::fromStdString(*text);
      }
      continue;
    }
    if (auto text = lesson::stepValueText(p, key, key.name))
      map[QString::fromStdString(key.name)] = QString::fromStdString(*text);
  }
  return map;
}

// Values a newer or older table no longer accepts are skipped: the session is a convenience, not a file.
void applyParameterMap(lesson::StepParameters& p, const QVariantMap& map) {
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string name = it.key().toStdString();
    const lesson::StepKey* key = lesson::findStepKey(name);
    if (!key || !key->control) continue;
    try {
      lesson::applyStepValue(p, *key, name, it.value().toString().toStdString(), {"the saved session"});
    } catch (const std::exception&) {
    }
  }
}

QVariantList cameraList(const Camera& c) {
  QVariantList v;
  for (const Vec3* p : {&c.position, &c.target, &c.up})
    for (int k = 0; k < 3; ++k) v << (*p)[k];
  v << c.fovYDegrees;
  return v;
}

std::optional<Camera> cameraFrom(const QVariant& value) {
  const QVariantList v = value.toList();
  if (v.size() != 10) return std::nullopt;
  Camera c;
  for (int k = 0; k < 3; ++k) {
    c.position[k] = v[k].toDouble();
    c.target[k] = v[3 + k].toDouble();
    c.up[k] = v[6 + k].toDouble();
  }
  c.fovYDegrees = v[9].toDouble();
  if ((c.target - c.position).norm() == 0 || !(c.fovYDegrees > 0 && c.fovYDegrees < 180)) return std::nullopt;
  return c;
}

}  // namespace

void MainWindow::saveSession() {
  if (!options_.screenshot.isEmpty() || mode_ == Mode::None) return;
  QSettings settings;
  settings.setValue("session/mode", mode_ == Mode::Scene ? "scene" : "lesson");
  settings.setValue("session/scene", mode_ == Mode::Scene ? scenePath_ : QString());
  settings.setValue("session/parameters", parameterMap(parameters_));
  if (primaryView_->hasMesh())
    settings.setValue("session/camera", cameraList(primaryView_->currentCamera()));
  else
    settings.remove("session/camera");
}

bool MainWindow::restoreSession() {
  QSettings settings;
  const QString mode = settings.value("session/mode").toString();
  const QVariantMap parameters = settings.value("session/parameters").toMap();
  pendingCamera_ = cameraFrom(settings.value("session/camera"));
  if (mode == "scene") {
    const QString path = settings.value("session/scene").toString();
    if (path.isEmpty() || QFileInfo::exists(path)) {
      sessionParameters_ = parameters;
      return openScene(path);
    }
  }
  const QString remembered = settings.value("position/lesson").toString();
  const int lessonIndex = library_->indexOf(remembered.toStdString());
  if (remembered.isEmpty() || lessonIndex < 0) {
    pendingCamera_.reset();
    return false;
  }
  const int step = settings.value("position/step", 0).toInt();
  // A step that took long last time (a benchmark) waits for the reader instead of occupying the machine.
  deferred_ = isLongStep(lessonIndex, step);
  sessionParameters_ = parameters;
  const bool opened = openLesson(remembered, step);
  deferred_ = deferred_ && opened;
  sessionParameters_.clear();
  return opened;
}

void MainWindow::applySessionParameters() {
  applyParameterMap(parameters_, sessionParameters_);
  sessionParameters_.clear();
}

bool MainWindow::recordComputeTime() {
  if (mode_ != Mode::Lesson || !options_.screenshot.isEmpty()) return false;
  const auto& lesson = library_->lessons()[static_cast<std::size_t>(lesson_)];
  const qint64 took = QDateTime::currentMSecsSinceEpoch() - computeStartedMs_;
  const bool wasLong = isLongStep(lesson_, step_);
  QSettings().setValue(stepKey(lesson.id, step_), took);
  return wasLong || took > kLongStepMs;
}

void MainWindow::keepStepResult() {
  const auto& lesson = library_->lessons()[static_cast<std::size_t>(lesson_)];
  CachedStepResult kept;
  kept.markdown = QString::fromStdString(result_->text);
  kept.figures = figures_->files();
  kept.captions = figures_->captions();
  kept.computed = QDateTime::currentDateTime();
  stepCache_.store(QString::fromStdString(lesson.id), step_, parameterMap(parameters_), kept);
}

bool MainWindow::showKeptResult() {
  const auto& lesson = library_->lessons()[static_cast<std::size_t>(lesson_)];
  const auto kept = stepCache_.load(QString::fromStdString(lesson.id), step_, parameterMap(parameters_));
  if (!kept) return false;
  showingKept_ = true;
  const QString when = QLocale().toString(kept->computed, QLocale::ShortFormat);
  setStepMarkdown(
      tr("*The results of %1, kept from then: press **Compute this step** below, or F5, to run it "
         "again.*\n\n%2")
          .arg(when, kept->markdown));
  if (figures_->showImages(kept->figures, kept->captions) > 0) tabs_->setCurrentWidget(figures_);
  // The kept result holds the figures and the text, not the solution: an empty 3D view and a player over
  // nothing would look broken, so they stay hidden until the step is computed.
  showViewPane(false);
  statusLabel_->setText(tr("Showing the results of %1: Go > Compute this step (F5) to recompute").arg(when));
  return true;
}

QString MainWindow::recentKey() const {
  return recentKey(lesson_, step_, parameters_);
}

QString MainWindow::recentKey(int lessonIndex, int step, const lesson::StepParameters& parameters) const {
  QString key = QString("%1/%2").arg(lessonIndex).arg(step);
  const QVariantMap values = parameterMap(parameters);
  for (auto it = values.begin(); it != values.end(); ++it)
    key += "/" + it.key() + "=" + it.value().toString();
  if (compare_) {
    const CompareChoice c = compareChoice();
    key += QString("/compare=%1,%2,%3")
               .arg(QString::fromStdString(c.solver), QString::fromStdString(c.method),
                    QString::fromStdString(c.mesh));
  }
  return key;
}

bool MainWindow::isLongStep(int lessonIndex, int step) const {
  if (!options_.screenshot.isEmpty()) return false;  // a screenshot is of the computed step
  const auto& lesson = library_->lessons()[static_cast<std::size_t>(lessonIndex)];
  if (step < 0 || step >= static_cast<int>(lesson.steps.size())) return false;
  if (lesson.steps[static_cast<std::size_t>(step)].stage == lesson::Stage::Benchmark) return true;
  return QSettings().value(stepKey(lesson.id, step), 0).toLongLong() > kLongStepMs;
}

void MainWindow::showViewPane(bool shown) {
  viewSplitter_->setVisible(shown && !largeFigure_);
  player_->setVisible(shown && !largeFigure_);
}

void MainWindow::computeNow() {
  if (mode_ == Mode::None) return;
  deferred_ = false;
  showingKept_ = false;
  showViewPane(true);
  computeButton_->hide();
  newStepPending_ = true;
  requestComputation();
}

void MainWindow::restoreParameters(const lesson::StepParameters& parameters) {
  if (mode_ == Mode::None) return;
  parameters_ = parameters;
  panel_->showParameters(parameters);
  requestComputation();
}

void MainWindow::zoomText(int steps) {
  // Presenter mode reads from the back of a lecture hall: body text of 32 px at least (a projector shows
  // 1920 x 1080 on a few metres), and the same zoom keys as in normal mode.
  for (int k = 0; k < std::abs(steps); ++k) textZoom_ *= steps > 0 ? 1.1 : 1.0 / 1.1;
  textZoom_ = std::clamp(textZoom_, 0.5, 4.0);
  if (!presenter_ && std::abs(textZoom_ - 1.0) < 1e-9) {
    // Back to the font the text had before any zoom, exactly.
    text_->setFont(normalTextFont_);
    return;
  }
  QFont font = normalTextFont_;
  const int normalPixels = QFontInfo(normalTextFont_).pixelSize();
  const int base = presenter_ ? std::max(32, normalPixels * 2) : normalPixels;
  font.setPixelSize(std::max(6, static_cast<int>(std::lround(base * textZoom_))));
  text_->setFont(font);  // the page's text and its equations follow the widget's font
}

void MainWindow::setStepMarkdown(const QString& markdown) {
  stepMarkdown_ = markdown;
  text_->setMarkdown(markdown);
}

void MainWindow::setLargeFigure(bool on) {
  largeFigure_ = on && figures_->figureCount() > 0;
  {
    const QSignalBlocker block(largeFigureAction_);
    largeFigureAction_->setChecked(largeFigure_);
  }
  // The figures tab takes the place of the 3D view and the player, at the size of the pane.
  showViewPane(!showingKept_);
  figures_->setFillPane(largeFigure_);
  if (largeFigure_) tabs_->setCurrentWidget(figures_);
}

void MainWindow::resetView() {
  if (!result_ || !primaryView_->hasMesh()) return;
  primaryView_->applyCamera(result_->camera);
  if (compare_) secondaryView_->syncCameraFrom(*primaryView_);
}

void MainWindow::showStandardView(StandardView view) {
  if (!result_ || !result_->scene || !primaryView_->hasMesh()) return;
  primaryView_->applyCamera(standardCamera(*result_->scene, view, result_->camera.fovYDegrees));
  if (compare_) secondaryView_->syncCameraFrom(*primaryView_);
}

// The display keys as the reader has them now (the step's values until the reader changes one).
void MainWindow::applyStepDisplay(const lesson::Step* step) {
  viz::SceneViewOptions options = primaryView_->viewOptions();
  if (step || mode_ == Mode::Scene) {
    const lesson::StepParameters& p = parameters_;
    options.image.exposure = p.exposure;
    options.image.toneMap = viz::toneMapFromName(p.toneMap);
    // Automatic exposure is found once per step and then kept: found anew for every result, it would
    // normalise a doubled light away and the picture would never change.
    if (p.exposure <= 0 && result_ && result_->mesh && result_->B.rows() > 0) {
      if (keptExposure_ <= 0)
        keptExposure_ = viz::autoExposure(result_->B, options.image.toneMap, &result_->mesh->emission);
      options.image.exposure = keptExposure_;
    }
    options.image.srgbGamma = p.gamma;
    options.image.smooth = p.smooth;
    options.image.showEdges = p.edges;
  } else {
    options = viz::SceneViewOptions{};
  }
  options.colourBar = false;
  primaryView_->setViewOptions(options);
  secondaryView_->setViewOptions(options);
}

void MainWindow::showIteration(int index) {
  if (!result_) return;
  auto show = [index](SceneView* view, const PipelineResult& r) {
    if (r.history.empty()) return;
    const int i = std::min(index, static_cast<int>(r.history.size()) - 1);
    view->setRadiosity(r.history[static_cast<std::size_t>(i)].B);
  };
  show(primaryView_, *result_);
  if (compare_ && result_->compared) show(secondaryView_, *result_->compared);
  chart_->setCurrent(index);
}

void MainWindow::selectElements(int first, int second) {
  if (!result_ || !result_->mesh) return;
  const int n = static_cast<int>(result_->mesh->size());
  if (first < 0 || first >= n) return;
  std::vector<int> elements{first};
  if (second >= 0 && second < n && second != first) elements.push_back(second);
  primaryView_->setHighlighted(elements);
  if (compare_) secondaryView_->setHighlighted(elements);
  if (second < 0) matrix_->selectElementRow(first);
  const Element& e = result_->mesh->elements[static_cast<std::size_t>(first)];
  const std::string& surface = result_->scene->surfaces[result_->scene->patches[e.patch].surface].name;
  QString text = tr("element %1 (patch %2, %3): B = (%4, %5, %6) W/m^2")
                     .arg(first)
                     .arg(e.patch)
                     .arg(QString::fromStdString(surface))
                     .arg(result_->B(first, 0), 0, 'g', 4)
                     .arg(result_->B(first, 1), 0, 'g', 4)
                     .arg(result_->B(first, 2), 0, 'g', 4);
  if (second >= 0 && result_->F)
    text += tr("; F[%1][%2] = %3").arg(first).arg(second).arg((*result_->F)(first, second), 0, 'g', 6);
  statusLabel_->setText(text);
}

void MainWindow::updateNavigation() {
  const bool lesson = mode_ == Mode::Lesson;
  backButton_->setVisible(lesson);
  nextButton_->setVisible(lesson);
  if (!lesson) {
    stepLabel_->setText(tr("Your scene"));
    return;
  }
  const auto& lessons = library_->lessons();
  const auto& current = lessons[static_cast<std::size_t>(lesson_)];
  // Word-wrapped, never elided; the tooltip repeats it with the step's own title.
  const QString label =
      tr("%1 - step %2 of %3").arg(lessonHeading(current)).arg(step_ + 1).arg(current.steps.size());
  stepLabel_->setText(label);
  stepLabel_->setToolTip(label + "\n" +
                         QString::fromStdString(current.steps[static_cast<std::size_t>(step_)].title));
  backButton_->setEnabled(step_ > 0 || lesson_ > 0);
  nextButton_->setEnabled(step_ + 1 < static_cast<int>(current.steps.size()) ||
                          lesson_ + 1 < static_cast<int>(lessons.size()));
}

void MainWindow::rememberPosition() {
  if (mode_ != Mode::Lesson || !options_.screenshot.isEmpty()) return;
  QSettings settings;
  settings.setValue("position/lesson",
                    QString::fromStdString(library_->lessons()[static_cast<std::size_t>(lesson_)].id));
  settings.setValue("position/step", step_);
  saveSession();
}

}  // namespace rt::app
