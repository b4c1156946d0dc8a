// The table of contents: chapters, their lessons in book order, and each lesson's steps. Activating an item
// opens that lesson (at its first step) or that step.
#pragma once

#include <QTreeWidget>
#include <vector>

#include "lesson/lesson.h"

namespace rt::app {

// "Lesson 9: Ray casting and Monte Carlo form factors": numbered by the lesson's `order:`, as the texts refer
// to one another ("lesson 9 estimated form factors by sampling"); a lesson without an order is its title.
QString lessonHeading(const lesson::Lesson& lesson);

class ContentsTree : public QTreeWidget {
  Q_OBJECT
 public:
  explicit ContentsTree(QWidget* parent = nullptr);
  void setLessons(const std::vector<lesson::Lesson>& lessons);
  // Marks the current step (without emitting stepActivated).
  void setCurrent(int lesson, int step);

 signals:
  void stepActivated(int lesson, int step);

 private:
  QTreeWidgetItem* findItem(int lesson, int step) const;
  bool updating_ = false;
};

}  // namespace rt::app
