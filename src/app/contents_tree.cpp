#include "app/contents_tree.h"

#include <QHeaderView>
#include <map>

namespace rt::app {
namespace {
constexpr int kLessonRole = Qt::UserRole;
constexpr int kStepRole = Qt::UserRole + 1;
}  // namespace

QString lessonHeading(const lesson::Lesson& lesson) {
  const QString title = QString::fromStdString(lesson.title);
  return lesson.order > 0 ? QObject::tr("Lesson %1: %2").arg(lesson.order).arg(title) : title;
}

ContentsTree::ContentsTree(QWidget* parent) : QTreeWidget(parent) {
  setHeaderHidden(true);
  setColumnCount(1);
  setObjectName("contents");
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (updating_ || !item) return;
    const QVariant lesson = item->data(0, kLessonRole);
    if (!lesson.isValid()) return;  // a chapter
    emit stepActivated(lesson.toInt(), item->data(0, kStepRole).toInt());
  });
}

void ContentsTree::setLessons(const std::vector<lesson::Lesson>& lessons) {
  updating_ = true;
  clear();
  std::map<std::string, QTreeWidgetItem*> chapters;
  for (std::size_t l = 0; l < lessons.size(); ++l) {
    const lesson::Lesson& lesson = lessons[l];
    const std::string chapterName = lesson.chapter.empty() ? std::string("Lessons") : lesson.chapter;
    QTreeWidgetItem*& chapter = chapters[chapterName];
    if (!chapter) {
      chapter = new QTreeWidgetItem(this, {QString::fromStdString(chapterName)});
      QFont bold = chapter->font(0);
      bold.setBold(true);
      chapter->setFont(0, bold);
      chapter->setFlags(Qt::ItemIsEnabled);
      chapter->setToolTip(0, QString::fromStdString(chapterName));
    }
    // A narrow dock elides long titles: every item carries its whole text as its tooltip.
    const QString heading = lessonHeading(lesson);
    auto* lessonItem = new QTreeWidgetItem(chapter, {heading});
    lessonItem->setData(0, kLessonRole, static_cast<int>(l));
    lessonItem->setData(0, kStepRole, 0);
    lessonItem->setToolTip(
        0, lesson.summary.empty() ? heading : heading + "\n" + QString::fromStdString(lesson.summary));
    for (std::size_t s = 0; s < lesson.steps.size(); ++s) {
      const QString text = QString("%1. %2").arg(s + 1).arg(QString::fromStdString(lesson.steps[s].title));
      auto* stepItem = new QTreeWidgetItem(lessonItem, {text});
      stepItem->setData(0, kLessonRole, static_cast<int>(l));
      stepItem->setData(0, kStepRole, static_cast<int>(s));
      stepItem->setToolTip(0, heading + "\n" + text);
    }
  }
  expandToDepth(0);
  updating_ = false;
}

QTreeWidgetItem* ContentsTree::findItem(int lesson, int step) const {
  for (int c = 0; c < topLevelItemCount(); ++c) {
    QTreeWidgetItem* chapter = topLevelItem(c);
    for (int l = 0; l < chapter->childCount(); ++l) {
      QTreeWidgetItem* lessonItem = chapter->child(l);
      if (lessonItem->data(0, kLessonRole).toInt() != lesson) continue;
      return step >= 0 && step < lessonItem->childCount() ? lessonItem->child(step) : lessonItem;
    }
  }
  return nullptr;
}

void ContentsTree::setCurrent(int lesson, int step) {
  updating_ = true;
  if (QTreeWidgetItem* item = findItem(lesson, step)) {
    setCurrentItem(item);
    scrollToItem(item);
  }
  updating_ = false;
}

}  // namespace rt::app
