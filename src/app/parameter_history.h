// Undo and redo of the reader's parameter changes (Ctrl+Z, Ctrl+Shift+Z): each change the panel applies is
// one entry, named by the keys it changed ("Undo bounces"). The history belongs to one step or scene: a new
// one starts with an empty history, as a document does when it is opened.
#pragma once

#include <QObject>
#include <QString>
#include <functional>

#include "lesson/lesson.h"

class QAction;
class QUndoStack;

namespace rt::app {

class ParameterHistory : public QObject {
  Q_OBJECT
 public:
  // `restore` puts parameters back (the window recomputes with them and shows them in the panel).
  ParameterHistory(std::function<void(const lesson::StepParameters&)> restore, QObject* parent = nullptr);

  // The reader changed `before` into `after` (already applied).
  void recordChange(const lesson::StepParameters& before, const lesson::StepParameters& after);
  void clear();
  bool canUndo() const;
  bool canRedo() const;
  void undo();
  void redo();
  // Menu actions whose text names what they would undo or redo, with the platform's standard shortcuts.
  QAction* createUndoAction(QObject* parent) const;
  QAction* createRedoAction(QObject* parent) const;

  // "bounces", "light-scale, reflectance.floor": the keys whose values differ.
  static QString changedKeys(const lesson::StepParameters& before, const lesson::StepParameters& after);

 private:
  QUndoStack* stack_ = nullptr;
  std::function<void(const lesson::StepParameters&)> restore_;
};

}  // namespace rt::app
