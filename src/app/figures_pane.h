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
  // Draws the figures showStep would draw for `key` into memory without showing them (a step computed
  // ahead): showStep with that key then shows them at once.
  void prepare(const lesson::Lesson& lesson, const lesson::Step& step, const lesson::StepResult& result,
               const QString& key);
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
  // Draws the step's figures other than the 3D view into a new folder: files, captions and images.
  struct Drawn;
  Drawn draw(const lesson::Lesson& lesson, const lesson::Step& step, const lesson::StepResult& result);
  void remember(Drawn drawn);
  void addFigure(const QPixmap& pixmap, const QString& path, const QString& caption);
  struct Figure {
    QLabel* caption;
    QLabel* label;
    QPixmap original;
  };
  std::vector<Figure> figures_;
  QStringList files_, captions_;
  // The figures drawn under the last keys given to showStep, the most recent first.
  struct Drawn {
    QString key;
    std::vector<QPixmap> images;
    QStringList files, captions;
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
