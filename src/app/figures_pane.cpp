#include "app/figures_pane.h"

#include <QDir>
#include <QLabel>
#include <QPixmap>
#include <QScrollBar>
#include <QStyle>
#include <QVBoxLayout>
#include <algorithm>
#include <stdexcept>

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

QSize FiguresPane::drawSize() const {
  constexpr int kLargest = 900, kSmallest = 480, kHigh = 680;
  const QMargins margins = layout_->contentsMargins();
  const int scrollBar = style()->pixelMetric(QStyle::PM_ScrollBarExtent);
  const int wide = viewport()->width() - margins.left() - margins.right() - scrollBar;
  // A caption of two lines above the figure.
  const int high = viewport()->height() - margins.top() - margins.bottom() - 2 * fontMetrics().lineSpacing() -
                   2 * layout_->spacing();
  const int shown = static_cast<int>(std::min(wide, high * kLargest / kHigh) * devicePixelRatioF());
  const int width = fill_ ? kLargest : std::clamp(shown, kSmallest, kLargest);
  return {width, width * kHigh / kLargest};
}

QString FiguresPane::newFolder() {
  return folder_.isValid() ? folder_.filePath(QString::number(++serial_)) : QString();
}

void FiguresPane::keep(const QString& key, std::shared_ptr<const StepFigures> figures) {
  if (key.isEmpty() || !figures) return;
  drawn_.remove_if([&](const Drawn& d) { return d.key == key; });
  drawn_.push_front({key, std::move(figures)});
  while (drawn_.size() > kDrawnKept) drawn_.pop_back();
}

int FiguresPane::showStep(const lesson::Lesson& lesson, const lesson::Step& step,
                          const lesson::StepResult& result, const QString& key) {
  clear();
  const auto kept = key.isEmpty() ? drawn_.end()
                                  : std::find_if(drawn_.begin(), drawn_.end(),
                                                 [&](const Drawn& d) { return d.key == key; });
  std::shared_ptr<const StepFigures> figures;
  if (kept != drawn_.end()) {
    figures = kept->figures;
    drawn_.splice(drawn_.begin(), drawn_, kept);
  } else {
    const QString folder = figureStep(step).views.empty() ? QString() : newFolder();
    figures = std::make_shared<StepFigures>(
        folder.isEmpty() ? StepFigures{} : drawStepFigures(lesson, step, result, folder, drawSize()));
    keep(key, figures);  // figures drawn without a key are not kept
  }
  if (!figures->error.isEmpty()) throw std::runtime_error(figures->error.toStdString());
  for (std::size_t k = 0; k < figures->images.size(); ++k)
    addFigure(QPixmap::fromImage(figures->images[k]), figures->files[static_cast<qsizetype>(k)],
              figures->captions[static_cast<qsizetype>(k)]);
  fitFigures();
  return count_;
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
