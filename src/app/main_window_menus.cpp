// MainWindow: the menus (each action with its shortcut, so that the menus show them and Help > Keys lists
// them), recent files, save dialogs that suggest a file name, Help > About and Help > Keys.
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSpinBox>

#include "app/camera_views.h"
#include "app/contents_tree.h"
#include "app/iteration_player.h"
#include "app/keys_dialog.h"
#include "app/lesson_session.h"
#include "app/main_window.h"
#include "app/parameter_history.h"
#include "app/scene_view.h"

namespace rt::app {
namespace {

constexpr int kRecentFiles = 8;
// The sides an exported view may have, in pixels.
constexpr int kExportMin = 240, kExportMax = 8192;

// An action whose shortcut also works while the menu bar is hidden (presenter mode): the window owns it too.
QAction* add(QMainWindow* window, QMenu* menu, const QString& text, const QList<QKeySequence>& keys) {
  QAction* action = menu->addAction(text);
  action->setShortcuts(keys);
  window->addAction(action);
  return action;
}

}  // namespace

QString MainWindow::suggestedFileName(const QString& what, const QString& extension) const {
  QString stem;
  if (mode_ == Mode::Lesson && lesson_ >= 0)
    stem = QString("%1-%2")
               .arg(QString::fromStdString(library_->lessons()[static_cast<std::size_t>(lesson_)].id))
               .arg(step_ + 1);
  else if (mode_ == Mode::Scene)
    stem = scenePath_.isEmpty() ? QString("cornell-box") : QFileInfo(scenePath_).completeBaseName();
  else
    stem = "radiosity";
  return QString("%1-%2.%3").arg(stem, what, extension);
}

QString MainWindow::exportFileDialog(const QString& title, const QString& filters, const QString& suggested,
                                     QSize* size) {
  QSettings settings;
  const QString folder = settings.value("export/folder", QDir::currentPath()).toString();
  QFileDialog dialog(this, title, folder, filters);
  dialog.setObjectName("exportDialog");
  dialog.setAcceptMode(QFileDialog::AcceptSave);
  dialog.setOption(QFileDialog::DontUseNativeDialog);  // the same dialog on every desktop (and in the tests)
  dialog.selectFile(suggested);
  const QString extension = QFileInfo(suggested).suffix();
  for (const QString& filter : dialog.nameFilters())
    if (filter.contains("*." + extension)) dialog.selectNameFilter(filter);
  // Choosing another type changes the suggested name's extension with it.
  connect(&dialog, &QFileDialog::filterSelected, &dialog, [&dialog](const QString& filter) {
    const int star = filter.indexOf("*.");
    if (star >= 0) dialog.setDefaultSuffix(filter.mid(star + 2).remove(')').section(' ', 0, 0));
  });
  dialog.setDefaultSuffix(extension);
  QSpinBox* width = nullptr;
  QSpinBox* height = nullptr;
  if (size) {
    // A row under the file type: the picture's size in pixels (a slide, a poster, a page of the notes).
    auto* grid = qobject_cast<QGridLayout*>(dialog.layout());
    auto* row = new QWidget(&dialog);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    width = new QSpinBox(row);
    height = new QSpinBox(row);
    for (QSpinBox* box : {width, height}) {
      box->setRange(kExportMin, kExportMax);
      box->setSuffix(tr(" px"));
    }
    width->setObjectName("exportWidth");
    height->setObjectName("exportHeight");
    width->setValue(size->width());
    height->setValue(size->height());
    layout->addWidget(width);
    layout->addWidget(new QLabel(QStringLiteral("×"), row));
    layout->addWidget(height);
    layout->addStretch(1);
    auto* label = new QLabel(tr("Picture size:"), &dialog);
    label->setBuddy(width);
    if (grid) {
      const int at = grid->rowCount();
      grid->addWidget(label, at, 0);
      grid->addWidget(row, at, 1, 1, std::max(1, grid->columnCount() - 1));
    }
  }
  if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return {};
  if (size) *size = QSize(width->value(), height->value());
  const QString path = dialog.selectedFiles().front();
  settings.setValue("export/folder", QFileInfo(path).absolutePath());
  return path;
}

QStringList MainWindow::recentFiles() const {
  return QSettings().value("recent/files").toStringList();
}

void MainWindow::addRecentFile(const QString& path) {
  if (!options_.screenshot.isEmpty()) return;
  QStringList files = recentFiles();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kRecentFiles) files.removeLast();
  QSettings().setValue("recent/files", files);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
  recentMenu_->clear();
  const QStringList files = recentFiles();
  int number = 0;
  for (const QString& file : files) {
    ++number;
    QAction* action = recentMenu_->addAction(QString("&%1 %2").arg(number).arg(QFileInfo(file).fileName()));
    action->setToolTip(file);
    action->setStatusTip(file);
    connect(action, &QAction::triggered, this, [this, file] { openScene(file); });
  }
  if (files.isEmpty()) recentMenu_->addAction(tr("(none yet)"))->setEnabled(false);
  recentMenu_->addSeparator();
  QAction* clear = recentMenu_->addAction(tr("&Clear the list"));
  clear->setEnabled(!files.isEmpty());
  connect(clear, &QAction::triggered, this, [this] {
    QSettings().remove("recent/files");
    rebuildRecentMenu();
  });
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  connect(add(this, file, tr("&Open scene..."), {QKeySequence::Open}), &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open scene"), QString(),
                                                      tr("Scenes (*.json *.obj);;All files (*)"));
    if (!path.isEmpty()) openScene(path);
  });
  recentMenu_ = file->addMenu(tr("Open &recent"));
  recentMenu_->setObjectName("recentMenu");
  rebuildRecentMenu();
  file->addAction(tr("Open the built-in &Cornell box"), this, [this] { openScene(QString()); });
  file->addSeparator();
  connect(add(this, file, tr("Export &view (PNG, SVG, PDF)..."), {QKeySequence(Qt::CTRL | Qt::Key_E)}),
          &QAction::triggered, this, [this] {
            QSize size = viewExportSize();
            const QString path =
                exportFileDialog(tr("Export view"), tr("PNG (*.png);;SVG (*.svg);;PDF (*.pdf)"),
                                 suggestedFileName("view", "png"), &size);
            if (!path.isEmpty()) exportView(path, size);
          });
  connect(add(this, file, tr("Export this step's &figures (SVG, PDF, PNG)..."),
              {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E)}),
          &QAction::triggered, this, [this] {
            const QString path =
                exportFileDialog(tr("Export the step's figures"), tr("SVG (*.svg);;PDF (*.pdf);;PNG (*.png)"),
                                 suggestedFileName("figures", "svg"));
            // The name the reader typed, its extension the format.
            const QFileInfo file(path);
            if (!path.isEmpty())
              exportStepFigures(file.absolutePath(), file.suffix().toLower(), file.completeBaseName());
          });
  const QString matrixFilters = tr("CSV (*.csv);;Matrix Market (*.mtx);;NumPy (*.npy);;LaTeX (*.tex)");
  for (const auto& [which, text] : {std::pair{QString("F"), tr("Export form factors &F...")},
                                    std::pair{QString("K"), tr("Export matrix &K = I - diag(rho) F...")},
                                    std::pair{QString("B"), tr("Export radiosity &B...")}}) {
    file->addAction(text, this, [this, which = which, matrixFilters] {
      const QString path =
          exportFileDialog(tr("Export %1").arg(which), matrixFilters, suggestedFileName(which, "csv"));
      if (!path.isEmpty()) exportMatrixFile(which, path);
    });
  }
  file->addAction(tr("Export &all figures of this lesson..."), this, [this] {
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Folder for the figures"));
    if (!folder.isEmpty()) exportAllFigures(folder);
  });
  file->addSeparator();
  connect(add(this, file, tr("&Quit"), {QKeySequence::Quit}), &QAction::triggered, this, &QWidget::close);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  undoAction_ = history_->createUndoAction(this);
  redoAction_ = history_->createRedoAction(this);
  edit->addAction(undoAction_);
  edit->addAction(redoAction_);
  addAction(undoAction_);
  addAction(redoAction_);

  QMenu* go = menuBar()->addMenu(tr("&Go"));
  connect(add(this, go, tr("&Next step"), {Qt::Key_Right, Qt::Key_PageDown}), &QAction::triggered, this,
          &MainWindow::nextStep);
  connect(add(this, go, tr("&Previous step"), {Qt::Key_Left, Qt::Key_PageUp}), &QAction::triggered, this,
          &MainWindow::previousStep);
  connect(add(this, go, tr("Play / &pause iterations"), {Qt::Key_Space}), &QAction::triggered, player_,
          &IterationPlayer::togglePlay);
  connect(add(this, go, tr("Next &iteration"), {Qt::Key_N}), &QAction::triggered, player_,
          &IterationPlayer::next);
  computeAction_ = add(this, go, tr("&Compute this step"), {Qt::Key_F5});
  connect(computeAction_, &QAction::triggered, this, &MainWindow::computeNow);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  presenterAction_ = add(this, view, tr("&Presenter mode"), {Qt::Key_F11});
  presenterAction_->setCheckable(true);
  presenterAction_->setShortcutContext(Qt::ApplicationShortcut);
  connect(presenterAction_, &QAction::toggled, this, &MainWindow::setPresenterMode);
  QAction* leave = new QAction(tr("Leave presenter mode"), this);
  leave->setShortcut(Qt::Key_Escape);
  addAction(leave);
  connect(leave, &QAction::triggered, this, [this] {
    if (presenter_) setPresenterMode(false);
  });
  largeFigureAction_ = add(this, view, tr("Step &figure in the main pane"), {Qt::Key_F});
  largeFigureAction_->setCheckable(true);
  connect(largeFigureAction_, &QAction::toggled, this, &MainWindow::setLargeFigure);
  compareAction_ = add(this, view, tr("&Compare side by side"), {QKeySequence(Qt::CTRL | Qt::Key_D)});
  compareAction_->setCheckable(true);
  connect(compareAction_, &QAction::toggled, this, &MainWindow::setCompareMode);
  QAction* edges = add(this, view, tr("Show mesh &edges"), {Qt::Key_E});
  edges->setCheckable(true);
  connect(edges, &QAction::toggled, this, [this](bool on) {
    primaryView_->setShowEdges(on);
    secondaryView_->setShowEdges(on);
  });
  connect(
      add(this, view, tr("&Zoom text in"), {QKeySequence::ZoomIn, QKeySequence(Qt::CTRL | Qt::Key_Equal)}),
      &QAction::triggered, this, [this] { zoomText(+1); });
  connect(add(this, view, tr("Zoom text &out"), {QKeySequence::ZoomOut}), &QAction::triggered, this,
          [this] { zoomText(-1); });
  view->addSeparator();
  connect(add(this, view, tr("&Reset view"), {Qt::Key_R}), &QAction::triggered, this, &MainWindow::resetView);
  connect(add(this, view, tr("&Front view"), {Qt::Key_1}), &QAction::triggered, this,
          [this] { showStandardView(StandardView::Front); });
  connect(add(this, view, tr("&Top view"), {Qt::Key_7}), &QAction::triggered, this,
          [this] { showStandardView(StandardView::Top); });
  connect(add(this, view, tr("&Side view"), {Qt::Key_3}), &QAction::triggered, this,
          [this] { showStandardView(StandardView::Side); });
  view->addSeparator();
  view->addAction(contentsDock_->toggleViewAction());
  view->addAction(parametersDock_->toggleViewAction());

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  connect(add(this, help, tr("&Keys..."), {QKeySequence::HelpContents}), &QAction::triggered, this,
          &MainWindow::showKeys);
  help->addAction(tr("&About Radiosity Textbook"), this, [this] {
    QMessageBox::about(
        this, tr("About Radiosity Textbook"),
        tr("<h3>Radiosity Textbook</h3><p>An interactive, step-by-step textbook of the radiosity method: "
           "form "
           "factors, the radiosity matrix, gathering and shooting, meshing and stochastic radiosity. Every "
           "number it shows is computed.</p><p>%1 lessons from %2.</p><p>Built with Qt %3 and VTK.</p>")
            .arg(library_->lessons().size())
            .arg(QString::fromStdString(library_->folders().lessons).toHtmlEscaped())
            .arg(QString::fromLatin1(qVersion())));
  });
}

std::vector<KeyBinding> MainWindow::keyBindings() {
  std::vector<KeyBinding> bindings = keyBindingsOf(this);
  // The 3D view's gestures are no actions.
  bindings.push_back({tr("Drag"), tr("Rotate the 3D view")});
  bindings.push_back({tr("Wheel"), tr("Zoom the 3D view")});
  bindings.push_back({tr("Click"), tr("Select an element (its row of F, its radiosity)")});
  bindings.push_back({tr("Click a cell of F"), tr("Outline both elements")});
  return bindings;
}

void MainWindow::showKeys() {
  auto* dialog = new KeysDialog(keyBindings(), this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->show();
  dialog->filterField()->setFocus();
}

}  // namespace rt::app
