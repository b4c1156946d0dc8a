#include "app/contents_tree.h"

#include <QHeaderView>
#include <map>

namespace rt::app {
namespace {
constexpr int kLessonRole = Qt::UserRole;
constexpr int kStepRole = Qt::UserRole + 1;
}  // namespace

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
    }
    auto* lessonItem = new QTreeWidgetItem(chapter, {QString::fromStdString(lesson.title)});
    lessonItem->setData(0, kLessonRole, static_cast<int>(l));
    lessonItem->setData(0, kStepRole, 0);
    lessonItem->setToolTip(0, QString::fromStdString(lesson.summary));
    for (std::size_t s = 0; s < lesson.steps.size(); ++s) {
      auto* stepItem = new QTreeWidgetItem(
          lessonItem, {QString("%1. %2").arg(s + 1).arg(QString::fromStdString(lesson.steps[s].title))});
      stepItem->setData(0, kLessonRole, static_cast<int>(l));
      stepItem->setData(0, kStepRole, static_cast<int>(s));
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
