#include "app/parameter_history.h"

#include <QAction>
#include <QUndoStack>

#include "lesson/step_keys.h"

namespace rt::app {
namespace {

class ParameterChange : public QUndoCommand {
 public:
  ParameterChange(const lesson::StepParameters& before, const lesson::StepParameters& after,
                  const std::function<void(const lesson::StepParameters&)>* restore)
      : before_(before), after_(after), restore_(restore) {
    setText(ParameterHistory::changedKeys(before, after));
  }
  void undo() override { (*restore_)(before_); }
  void redo() override {
    // Pushing a change calls redo at once; that change is already applied.
    if (first_) {
      first_ = false;
      return;
    }
    (*restore_)(after_);
  }

 private:
  lesson::StepParameters before_, after_;
  const std::function<void(const lesson::StepParameters&)>* restore_;
  bool first_ = true;
};

}  // namespace

ParameterHistory::ParameterHistory(std::function<void(const lesson::StepParameters&)> restore,
                                   QObject* parent)
    : QObject(parent), stack_(new QUndoStack(this)), restore_(std::move(restore)) {}

void ParameterHistory::recordChange(const lesson::StepParameters& before,
                                    const lesson::StepParameters& after) {
  stack_->push(new ParameterChange(before, after, &restore_));
}

void ParameterHistory::clear() {
  stack_->clear();
}

bool ParameterHistory::canUndo() const {
  return stack_->canUndo();
}

bool ParameterHistory::canRedo() const {
  return stack_->canRedo();
}

void ParameterHistory::undo() {
  stack_->undo();
}

void ParameterHistory::redo() {
  stack_->redo();
}

QAction* ParameterHistory::createUndoAction(QObject* parent) const {
  QAction* action = stack_->createUndoAction(parent, tr("&Undo"));
  action->setShortcut(QKeySequence::Undo);
  return action;
}

QAction* ParameterHistory::createRedoAction(QObject* parent) const {
  QAction* action = stack_->createRedoAction(parent, tr("&Redo"));
  // Ctrl+Shift+Z everywhere, Ctrl+Y too where the platform says so.
  QList<QKeySequence> keys{QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)};
  for (const QKeySequence& key : QKeySequence::keyBindings(QKeySequence::Redo))
    if (!keys.contains(key)) keys.append(key);
  action->setShortcuts(keys);
  return action;
}

QString ParameterHistory::changedKeys(const lesson::StepParameters& before,
                                      const lesson::StepParameters& after) {
  QStringList names;
  for (const lesson::StepKey& key : lesson::stepKeyTable()) {
    if (!key.control) continue;
    if (key.name == "reflectance") {
      for (const auto& [surface, rho] : after.reflectance) {
        auto it = before.reflectance.find(surface);
        if (it == before.reflectance.end() || !(it->second - rho).isZero(0))
          names << QString::fromStdString("reflectance." + surface);
      }
      for (const auto& [surface, rho] : before.reflectance)
        if (after.reflectance.count(surface) == 0) names << QString::fromStdString("reflectance." + surface);
      continue;
    }
    if (lesson::stepValueText(before, key, key.name) != lesson::stepValueText(after, key, key.name))
      names << QString::fromStdString(key.name);
  }
  return names.isEmpty() ? tr("parameters") : names.join(", ");
}

}  // namespace rt::app
