#include "app/figures_pane.h"

#include <QDir>
#include <QLabel>
#include <QPixmap>
#include <QScrollBar>
#include <QStyle>
#include <QVBoxLayout>
#include <algorithm>

#include "viz/lesson_figures.h"

namespace rt::app {

FiguresPane::FiguresPane(QWidget* parent) : QScrollArea(parent) {
  setWidgetResizable(true);
  content_ = new QWidget(this);
  layout_ = new QVBoxLayout(content_);
  layout_->addStretch(1);
  setWidget(content_);
}

void FiguresPane::clear() {
  while (layout_->count() > 1) {
    QLayoutItem* item = layout_->takeAt(0);
    delete item->widget();
    delete item;
  }
  figures_.clear();
  files_.clear();
  captions_.clear();
  count_ = 0;
}

namespace {

// As many steps' figures as the window keeps results of (RecentResults): a revisit finds both.
constexpr std::size_t kDrawnKept = 16;

}  // namespace

bool FiguresPane::addFigure(const QString& path, const QString& text) {
  QPixmap pixmap(path);
  if (pixmap.isNull()) return false;  // vector-only formats are not shown here
  addFigure(pixmap, path, text);
  return true;
}

void FiguresPane::addFigure(const QPixmap& pixmap, const QString& path, const QString& text) {
  auto* caption = new QLabel(text, content_);
  caption->setWordWrap(true);
  auto* image = new QLabel(content_);
  image->setObjectName("figure");
  figures_.push_back({caption, image, pixmap});
  files_.push_back(path);
  captions_.push_back(text);
  layout_->insertWidget(layout_->count() - 1, caption);
  layout_->insertWidget(layout_->count() - 1, image);
  ++count_;
}

int FiguresPane::showImages(const QStringList& files, const QStringList& captions) {
  clear();
  for (qsizetype k = 0; k < files.size(); ++k)
    addFigure(files[k], k < captions.size() ? captions[k] : QString());
  fitFigures();
  return count_;
}

FiguresPane::Drawn FiguresPane::draw(const lesson::Lesson& lesson, const lesson::Step& step,
                                     const lesson::StepResult& result) {
  Drawn drawn;
  lesson::Step others = step;
  others.views.clear();
  for (lesson::View v : step.views)
    // The walkthrough is flown in the 3D view (CameraPathPlayer), not drawn as frames here.
    if (v != lesson::View::Scene && v != lesson::View::Walkthrough) others.views.push_back(v);
  if (others.views.empty() || !folder_.isValid()) return drawn;
  // A fresh folder per call: the files of the previous step may still be on screen while these are written.
  const QString dir = folder_.filePath(QString::number(++serial_));
  viz::StepFigureSettings settings;
  settings.width = 900;
  settings.height = 680;
  const auto figures = viz::renderStepFigures(lesson, others, result, dir.toStdString(), settings);
  const auto files = others.figureFiles();
  for (std::size_t k = 0; k < files.size(); ++k) {
    const QString path = QDir(dir).filePath(QString::fromStdString(files[k]));
    QPixmap image(path);
    if (image.isNull()) continue;  // vector-only formats are not shown here
    drawn.images.push_back(image);
    drawn.files << path;
    drawn.captions << (k < figures.size() ? QString::fromStdString(figures[k].caption) : QString());
  }
  return drawn;
}

void FiguresPane::remember(Drawn drawn) {
  if (drawn.key.isEmpty()) return;
  drawn_.remove_if([&](const Drawn& d) { return d.key == drawn.key; });
  drawn_.push_front(std::move(drawn));
  if (drawn_.size() > kDrawnKept) drawn_.pop_back();
}

int FiguresPane::showStep(const lesson::Lesson& lesson, const lesson::Step& step,
                          const lesson::StepResult& result, const QString& key) {
  clear();
  const auto kept = key.isEmpty() ? drawn_.end()
                                  : std::find_if(drawn_.begin(), drawn_.end(),
                                                 [&](const Drawn& d) { return d.key == key; });
  if (kept != drawn_.end()) {
    drawn_.splice(drawn_.begin(), drawn_, kept);
  } else {
    Drawn drawn = draw(lesson, step, result);
    drawn.key = key;
    drawn_.push_front(std::move(drawn));
  }
  const Drawn& d = drawn_.front();
  for (std::size_t k = 0; k < d.images.size(); ++k) addFigure(d.images[k], d.files[k], d.captions[k]);
  fitFigures();
  // Figures drawn without a key are not kept.
  if (key.isEmpty()) drawn_.pop_front();
  while (drawn_.size() > kDrawnKept) drawn_.pop_back();
  return count_;
}

void FiguresPane::prepare(const lesson::Lesson& lesson, const lesson::Step& step,
                          const lesson::StepResult& result, const QString& key) {
  if (key.isEmpty() ||
      std::any_of(drawn_.begin(), drawn_.end(), [&](const Drawn& d) { return d.key == key; }))
    return;
  Drawn drawn = draw(lesson, step, result);
  drawn.key = key;
  remember(std::move(drawn));
}

void FiguresPane::resizeEvent(QResizeEvent* event) {
  QScrollArea::resizeEvent(event);
  fitFigures();
}

void FiguresPane::setFillPane(bool fill) {
  fill_ = fill;
  fitFigures();
}

void FiguresPane::fitFigures() {
  const QMargins margins = layout_->contentsMargins();
  // The room of the vertical scroll bar is kept whether it shows or not: a figure fitted before it appears
  // would be cut at the right when it does.
  const int scrollBar =
      verticalScrollBar()->isVisible() ? 0 : style()->pixelMetric(QStyle::PM_ScrollBarExtent);
  const int available = std::max(64, viewport()->width() - margins.left() - margins.right() - scrollBar);
  for (Figure& figure : figures_) {
    // The figure and its caption fit the pane's height too: a figure is seen whole.
    const int height = std::max(64, viewport()->height() - margins.top() - margins.bottom() -
                                        figure.caption->heightForWidth(available) - 2 * layout_->spacing());
    const int fitted =
        std::min(available, static_cast<int>(static_cast<double>(height) * figure.original.width() /
                                             std::max(1, figure.original.height())));
    const int width = fill_ ? std::max(64, fitted) : std::max(64, std::min(figure.original.width(), fitted));
    if (figure.label->pixmap().width() == width) continue;
    figure.label->setPixmap(figure.original.scaledToWidth(width, Qt::SmoothTransformation));
  }
}

}  // namespace rt::app
