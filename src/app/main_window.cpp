// MainWindow: construction of the widgets, menus, shortcuts, presenter and compare modes, exports.
// Navigation and results are in main_window_steps.cpp.
#include "app/main_window.h"
#include "app/camera_path_player.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QVBoxLayout>

#include "app/contents_tree.h"
#include "app/exercise_panel.h"
#include "app/exports.h"
#include "app/figure_export.h"
#include "app/figures_pane.h"
#include "app/iteration_player.h"
#include "app/lesson_session.h"
#include "app/matrix_view.h"
#include "app/parameter_history.h"
#include "app/parameter_panel.h"
#include "app/progress_strip.h"
#include "app/residual_chart.h"
#include "app/scene_view.h"
#include "app/wording.h"
#include "core/formfactor/formfactor_method.h"
#include "core/solvers/solver.h"
#include "plugins/optional_methods.h"

namespace rt::app {

MainWindow::MainWindow(const AppOptions& options, std::unique_ptr<LessonLibrary> library, QWidget* parent)
    : QMainWindow(parent), options_(options), library_(std::move(library)) {
  setWindowTitle(tr("Radiosity Textbook"));
  registerOptionalMethods();
  if (!library_) library_ = std::make_unique<LessonLibrary>(lesson::defaultFolders());
  normalLook_ = currentLook();
  runner_ = new ComputationRunner(this);
  connect(runner_, &ComputationRunner::finished, this, &MainWindow::showResult);
  connect(runner_, &ComputationRunner::failed, this, &MainWindow::showError);
  connect(runner_, &ComputationRunner::cancelled, this, [this] {
    showStale(false);
    newStepPending_ = false;
    statusLabel_->setText(tr("Cancelled: the previous result is still shown."));
  });
  connect(runner_, &ComputationRunner::busyChanged, this, &MainWindow::setBusy);
  prefetch_ = new ComputationRunner(this);
  connect(prefetch_, &ComputationRunner::finished, this, &MainWindow::keepPrefetched);
  // Overtaken by what the reader asked for, or by another step: the step now next is computed ahead in its
  // turn (nothing is done when it is in memory already).
  connect(prefetch_, &ComputationRunner::cancelled, this, &MainWindow::prefetchNextStep);
  connect(runner_, &ComputationRunner::progress, this,
          [this](double fraction, const QString& stage) { progress_->setProgress(fraction, stage); });
  history_ = new ParameterHistory([this](const lesson::StepParameters& p) { restoreParameters(p); }, this);
  buildUi();
  buildMenus();
  contents_->setLessons(library_->lessons());
  normalTextFont_ = text_->font();
  // Explicit, so that setting it back gives exactly this size whatever the application's font is then.
  if (normalTextFont_.pointSizeF() > 0)
    normalTextFont_.setPointSizeF(normalTextFont_.pointSizeF());
  else
    normalTextFont_.setPixelSize(normalTextFont_.pixelSize());
  resize(options.size);
  fitToWidth();
}

MainWindow::~MainWindow() {
  // The workers may be inside the lesson library: stop them before the library goes.
  delete figureExport_;
  figureExport_ = nullptr;
  delete prefetch_;
  prefetch_ = nullptr;
  delete runner_;
  runner_ = nullptr;
  if (presenter_) applyLook(normalLook_);
}

bool MainWindow::viewsShown() const {
  return !viewsPane_->isHidden();
}

bool MainWindow::busy() const {
  return runner_ && runner_->busy();
}

void MainWindow::closeEvent(QCloseEvent* event) {
  rememberPosition();
  saveSession();
  if (runner_) runner_->cancel();
  cancelFigureExport();
  QMainWindow::closeEvent(event);
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
  if (watched == viewsPane_ && staleCover_->isVisible() &&
      (event->type() == QEvent::Resize || event->type() == QEvent::Move))
    staleCover_->setGeometry(QRect(viewsPane_->mapTo(this, QPoint(0, 0)), viewsPane_->size()));
  if ((watched == text_ || watched == text_->viewport()) && event->type() == QEvent::ShortcutOverride) {
    auto* key = static_cast<QKeyEvent*>(event);
    const bool navigation = key->key() == Qt::Key_Left || key->key() == Qt::Key_Right ||
                            key->key() == Qt::Key_PageUp || key->key() == Qt::Key_PageDown ||
                            key->key() == Qt::Key_Space;
    if (navigation && key->modifiers() == Qt::NoModifier) {
      event->ignore();  // not the text's: the window's shortcut runs
      return true;
    }
  }
  return QMainWindow::eventFilter(watched, event);
}

void MainWindow::buildUi() {
  // Centre: the step's text | (views, player, chart and matrix).
  auto* centre = new QSplitter(Qt::Horizontal, this);
  centre_ = centre;
  auto* textPane = new QWidget(centre);
  auto* textLayout = new QVBoxLayout(textPane);
  textLayout->setContentsMargins(4, 4, 4, 4);
  text_ = new LessonTextView(textPane);
  text_->setObjectName("stepText");
  text_->installEventFilter(this);
  text_->viewport()->installEventFilter(this);
  auto* navigation = new QHBoxLayout();
  backButton_ = new QPushButton(tr("< Back"), textPane);
  nextButton_ = new QPushButton(tr("Next >"), textPane);
  backButton_->setToolTip(tr("Previous step (Left, Page Up)"));
  nextButton_->setToolTip(tr("Next step (Right, Page Down)"));
  stepLabel_ = new QLabel(textPane);
  stepLabel_->setAlignment(Qt::AlignCenter);
  stepLabel_->setWordWrap(true);  // a long lesson title must not widen the window
  // The lesson and step on their own line: between the buttons a long title would wrap word by word.
  navigation->addWidget(backButton_);
  navigation->addStretch(1);
  navigation->addWidget(nextButton_);
  // A long step of a restored session waits for the reader: this button (or F5) computes it.
  computeButton_ = new QPushButton(tr("Compute this step (F5)"), textPane);
  computeButton_->setObjectName("computeButton");
  computeButton_->hide();
  connect(computeButton_, &QPushButton::clicked, this, &MainWindow::computeNow);
  textLayout->addWidget(text_, 1);
  textLayout->addWidget(computeButton_);
  textLayout->addWidget(stepLabel_);
  textLayout->addLayout(navigation);
  connect(backButton_, &QPushButton::clicked, this, &MainWindow::previousStep);
  connect(nextButton_, &QPushButton::clicked, this, &MainWindow::nextStep);

  auto* right = new QSplitter(Qt::Vertical, centre);
  viewsPane_ = right;
  // Over the views while a new step computes: what they show belongs to the previous step and must look it.
  // A child of the window, not of the splitter (which would make it one of its panes).
  staleCover_ = new QLabel(tr("Computing this step...\nThe views still show the previous one."), this);
  staleCover_->setObjectName("staleCover");
  staleCover_->setAlignment(Qt::AlignCenter);
  staleCover_->setWordWrap(true);
  staleCover_->setStyleSheet("background-color: rgba(32, 32, 32, 190); color: white; font-size: 15pt;");
  staleCover_->hide();
  viewsPane_->installEventFilter(this);
  viewSplitter_ = new QSplitter(Qt::Horizontal, right);
  primaryView_ = new SceneView(viewSplitter_);
  primaryView_->setObjectName("primaryView");
  secondaryView_ = new SceneView(viewSplitter_);
  secondaryView_->setObjectName("secondaryView");
  secondaryView_->hide();
  auto* lower = new QWidget(right);
  auto* lowerLayout = new QVBoxLayout(lower);
  lowerLayout->setContentsMargins(0, 0, 0, 0);
  player_ = new IterationPlayer(lower);
  pathPlayer_ = new CameraPathPlayer(lower);
  tabs_ = new QTabWidget(lower);
  chart_ = new ResidualChart(tabs_);
  matrix_ = new MatrixView(tabs_);
  tabs_->addTab(chart_, tr("Convergence"));
  tabs_->addTab(matrix_, tr("Form factors F"));
  figures_ = new FiguresPane(tabs_);
  tabs_->addTab(figures_, tr("Step figures"));
  lowerLayout->addWidget(player_);
  lowerLayout->addWidget(pathPlayer_);
  lowerLayout->addWidget(tabs_, 1);
  right->addWidget(viewSplitter_);
  right->addWidget(lower);
  right->setStretchFactor(0, 3);
  right->setStretchFactor(1, 1);
  right->setSizes({620, 380});  // proportions: the 3D view gets most of the height
  centre->addWidget(textPane);
  centre->addWidget(right);
  // An exercise's answer fields stand where the views are on other steps (an exercise has no scene), not
  // under the text: growing and shrinking the typeset text's web view at every step made Qt WebEngine
  // corrupt the heap.
  exercise_ = new ExercisePanel(centre);
  centre->addWidget(exercise_);
  // The hint and the solution go under the step's text, typeset with it, and the page scrolls to them.
  connect(exercise_, &ExercisePanel::notesRequested, this,
          [this](const QString& notes) { text_->setMarkdown(stepMarkdown_ + "\n\n---\n\n" + notes, true); });
  centre->setStretchFactor(0, 2);
  centre->setStretchFactor(1, 5);
  centre->setStretchFactor(2, 5);
  centre->setCollapsible(2, false);
  centre->setSizes({380, 900, 900});  // the views or the answer fields: one of the two is shown
  setCentralWidget(centre);

  // The shared camera of compare mode: whichever view the reader moves, the other follows.
  connect(primaryView_, &VtkWidget::cameraInteraction, this, [this] {
    if (compare_) secondaryView_->syncCameraFrom(*primaryView_);
  });
  connect(secondaryView_, &VtkWidget::cameraInteraction, this, [this] {
    if (compare_) primaryView_->syncCameraFrom(*secondaryView_);
  });
  connect(player_, &IterationPlayer::currentChanged, this, &MainWindow::showIteration);
  connect(pathPlayer_, &CameraPathPlayer::cameraChanged, this, [this](const Camera& camera) {
    primaryView_->noteCameraMotion();  // a flight is drawn with the stand-in of a large mesh
    primaryView_->applyCamera(camera);
    if (compare_) secondaryView_->syncCameraFrom(*primaryView_);
  });
  connect(primaryView_, &SceneView::elementPicked, this, [this](int e) { selectElements(e, -1); });
  connect(secondaryView_, &SceneView::elementPicked, this, [this](int e) { selectElements(e, -1); });
  connect(matrix_, &MatrixView::elementsSelected, this, &MainWindow::selectElements);

  // Left: contents. Right: parameters and compare.
  contents_ = new ContentsTree(this);
  contents_->setMinimumWidth(180);
  contentsDock_ = new QDockWidget(tr("Contents"), this);
  contentsDock_->setObjectName("contentsDock");
  contentsDock_->setWidget(contents_);
  addDockWidget(Qt::LeftDockWidgetArea, contentsDock_);
  connect(contents_, &ContentsTree::stepActivated, this, [this](int l, int s) { openStep(l, s); });

  auto* side = new QWidget(this);
  auto* sideLayout = new QVBoxLayout(side);
  panel_ = new ParameterPanel(side);
  connect(panel_, &ParameterPanel::parametersChanged, this, &MainWindow::applyParameters);
  auto* compareForm = new QFormLayout();
  compareBox_ = new QCheckBox(tr("Compare side by side"), side);
  compareSolver_ = new QComboBox(side);
  compareMethod_ = new QComboBox(side);
  compareMesh_ = new QComboBox(side);
  compareMesh_->setObjectName("compareMesh");
  compareMesh_->setToolTip(tr("Half or twice the subdivision, or a mesh that follows the light"));
  for (QComboBox* box : {compareSolver_, compareMethod_, compareMesh_}) {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(8);
  }
  compareSolver_->addItem(tr("(same solver)"));
  for (const auto& n : solverNames()) compareSolver_->addItem(QString::fromStdString(n));
  compareMethod_->addItem(tr("(same method)"));
  addFormFactorMethodItems(compareMethod_);
  compareMesh_->addItem(tr("(same mesh)"));
  for (const auto& n : compareMeshChoices()) compareMesh_->addItem(QString::fromStdString(n));
  if (compareSolver_->findText("jacobi") >= 0) compareSolver_->setCurrentText("jacobi");
  compareForm->addRow(compareBox_);
  compareForm->addRow(tr("Right: solver"), compareSolver_);
  compareForm->addRow(tr("Right: F method"), compareMethod_);
  compareForm->addRow(tr("Right: mesh"), compareMesh_);
  sideLayout->addWidget(panel_);
  sideLayout->addLayout(compareForm);
  sideLayout->addStretch(1);
  connect(compareBox_, &QCheckBox::toggled, this, &MainWindow::setCompareMode);
  auto recompareIfOn = [this] {
    if (compare_) requestComputation();
  };
  connect(compareSolver_, &QComboBox::currentTextChanged, this, recompareIfOn);
  connect(compareMethod_, &QComboBox::currentTextChanged, this, recompareIfOn);
  connect(compareMesh_, &QComboBox::currentTextChanged, this, recompareIfOn);
  // Scrollable, so that the panel never forces the window wider than asked for (--size, small screens).
  auto* sideScroll = new QScrollArea(this);
  sideScroll->setWidgetResizable(true);
  // Whatever does not fit stays reachable (never cut off at the window's edge).
  sideScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  sideScroll->setWidget(side);
  sideScroll->setMinimumWidth(240);
  parametersDock_ = new QDockWidget(tr("Parameters"), this);
  parametersDock_->setObjectName("parametersDock");
  parametersDock_->setWidget(sideScroll);
  addDockWidget(Qt::RightDockWidgetArea, parametersDock_);

  statusLabel_ = new QLabel(this);
  statusLabel_->setObjectName("statusMessage");
  progress_ = new ProgressStrip(this);
  // Presenter mode hides the status bar; the class still has to see that something runs and how to stop it.
  connect(progress_, &ProgressStrip::appeared, this, [this] {
    if (presenter_) statusBar()->show();
  });
  connect(progress_, &ProgressStrip::cancelRequested, this, [this] {
    cancelComputation();
    cancelFigureExport();
  });
  statusBar()->addWidget(statusLabel_, 1);
  statusBar()->addPermanentWidget(progress_);
  // `radiosity lesson check` reports a broken formula at its line; a lesson opened without that check still
  // says so here (the page shows the formula's TeX in red) rather than leaving a reader to guess.
  connect(text_, &LessonTextView::lessonLinkClicked, this, [this](const QString& id) { openLesson(id); });
  connect(text_, &LessonTextView::typeset, this, [this](int, const QStringList& errors) {
    if (errors.isEmpty()) return;
    statusLabel_->setText(tr("A formula on this page does not typeset: %1").arg(errors.first()));
    qWarning("radiosity-textbook: a formula does not typeset: %s", qPrintable(errors.first()));
  });
}

void MainWindow::setCompareMode(bool on) {
  if (compare_ == on) return;
  compare_ = on;
  {
    const QSignalBlocker a(compareBox_), b(compareAction_);
    compareBox_->setChecked(on);
    compareAction_->setChecked(on);
  }
  secondaryView_->setVisible(on);
  if (on) secondaryView_->syncCameraFrom(*primaryView_);
  if (mode_ != Mode::None) requestComputation();
}

CompareChoice MainWindow::compareChoice() const {
  auto chosen = [](const QComboBox* box) {
    return box->currentIndex() > 0 ? box->currentText().toStdString() : std::string();
  };
  return CompareChoice{chosen(compareSolver_), chosen(compareMethod_), chosen(compareMesh_)};
}

void MainWindow::setCompareChoice(const CompareChoice& choice) {
  // One recomputation for the whole choice, not one per combo box.
  {
    const QSignalBlocker a(compareSolver_), b(compareMethod_), c(compareMesh_);
    auto choose = [](QComboBox* box, const std::string& value) {
      const int index = value.empty() ? 0 : box->findText(QString::fromStdString(value));
      box->setCurrentIndex(std::max(0, index));
    };
    choose(compareSolver_, choice.solver);
    choose(compareMethod_, choice.method);
    choose(compareMesh_, choice.mesh);
  }
  if (compare_ && mode_ != Mode::None) requestComputation();
}

void MainWindow::showError(const QString& coreMessage) {
  showStale(false);
  const QString message = inAppTerms(coreMessage);
  lastError_ = message;
  if (newStepPending_ && mode_ == Mode::Lesson) {
    // The step's own text stays readable, with what went wrong above it.
    const lesson::Step& step =
        library_->lessons()[static_cast<std::size_t>(lesson_)].steps[static_cast<std::size_t>(step_)];
    setStepMarkdown(QString("## %1\n\n> **This step could not be computed:** %2\n\n%3")
                        .arg(QString::fromStdString(step.title), message.toHtmlEscaped(),
                             QString::fromStdString(step.text)));
  }
  newStepPending_ = false;
  statusLabel_->setText(tr("Error: %1").arg(message));
  if (options_.screenshot.isEmpty() && isVisible() && !blocking_)
    QMessageBox::warning(this, tr("Radiosity Textbook"), message);
}

void MainWindow::setBusy(bool busy) {
  if (busy)
    showProgressStrip(tr("Computing"));
  else if (!figureExport_)
    hideProgressStrip();
}

}  // namespace rt::app
