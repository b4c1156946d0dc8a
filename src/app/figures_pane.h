// The step's other views (hemicube, Nusselt disk, rays, matrix, charts...) as the viz layer draws them for
// the book: the same function as `radiosity lesson render`, shown as images under their captions.
#pragma once

#include <QPixmap>
#include <QScrollArea>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <list>
#include <vector>

#include <memory>

#include "app/step_figures.h"
#include "lesson/lesson.h"
#include "lesson/step_result.h"

class QLabel;
class QVBoxLayout;

namespace rt::app {

class FiguresPane : public QScrollArea {
  Q_OBJECT
 public:
  explicit FiguresPane(QWidget* parent = nullptr);
  // Draws every view of the step except the live 3D scene view. Returns how many figures are shown; throws
  // std::runtime_error when drawing fails. `key`, when given, names the step with its settings (as the
  // window's recent results do): the figures of the last few keys are kept in memory and shown again at once
  // when their key comes back, instead of being drawn again.
  int showStep(const lesson::Lesson& lesson, const lesson::Step& step, const lesson::StepResult& result,
               const QString& key = QString());
  // Keeps figures drawn elsewhere (on the worker thread, with the step's computation) under `key`: showStep
  // with that key then shows them at once.
  void keep(const QString& key, std::shared_ptr<const StepFigures> figures);
  // A new folder for drawStepFigures (the files of the figures on screen stay where they are).
  QString newFolder();
  // The size to draw a figure at: as large as the pane shows one, in device pixels, from 480 x 363 up to
  // 900 x 680 (the largest when it fills the main pane). A software renderer's frame costs in proportion to
  // its pixels, and a figure drawn larger than the pane is only scaled down to fit.
  QSize drawSize() const;
  // Shows figure images kept from an earlier run (a restored session's long step), under their captions.
  int showImages(const QStringList& files, const QStringList& captions);
  void clear();
  int figureCount() const { return count_; }
  // The image files and captions on show (to keep them with a long step's result).
  const QStringList& files() const { return files_; }
  const QStringList& captions() const { return captions_; }
  // Off: each figure with its caption shrinks to the pane's width and height (a step's figure is seen whole;
  // several are scrolled through), never grows past its own size. On (a figure in the main pane): each fills
  // the pane's width and height, keeping its proportions.
  void setFillPane(bool fill);
  bool fillsPane() const { return fill_; }

 protected:
  // Figures are fitted to the pane again, so a whole chart with its legend is on screen however the docks
  // are arranged.
  void resizeEvent(QResizeEvent* event) override;

 private:
  void fitFigures();
  bool addFigure(const QString& path, const QString& caption);
  void addFigure(const QPixmap& pixmap, const QString& path, const QString& caption);
  struct Figure {
    QLabel* caption;
    QLabel* label;
    QPixmap original;
  };
  std::vector<Figure> figures_;
  QStringList files_, captions_;
  // The figures drawn under the last keys given to showStep or keep, the most recent first.
  struct Drawn {
    QString key;
    std::shared_ptr<const StepFigures> figures;
  };
  std::list<Drawn> drawn_;
  QTemporaryDir folder_;
  QWidget* content_ = nullptr;
  QVBoxLayout* layout_ = nullptr;
  int count_ = 0;
  int serial_ = 0;
  bool fill_ = false;
};

}  // namespace rt::app
