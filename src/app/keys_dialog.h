// Help > Keys: every key and mouse gesture of the window in one table, with a filter field ("zoom", "Ctrl",
// "iteration"). The rows are read from the window's actions, so that the list cannot miss a shortcut or name
// one that no longer exists; the gestures of the 3D view, which are no actions, are added by the caller.
#pragma once

#include <QDialog>
#include <QString>
#include <vector>

class QLineEdit;
class QTableWidget;
class QWidget;

namespace rt::app {

struct KeyBinding {
  QString keys;  // "Ctrl+Z", "Right, PgDown", "Drag"
  QString what;  // "Undo", "Next step"
};

// The shortcuts of every action of `window` and of its menus (each action once, "&" removed from its text).
std::vector<KeyBinding> keyBindingsOf(QWidget* window);

class KeysDialog : public QDialog {
  Q_OBJECT
 public:
  KeysDialog(const std::vector<KeyBinding>& bindings, QWidget* parent = nullptr);
  QLineEdit* filterField() const { return filter_; }
  QTableWidget* table() const { return table_; }
  // Rows shown after filtering.
  int visibleRows() const;

 private:
  void applyFilter(const QString& text);
  QLineEdit* filter_ = nullptr;
  QTableWidget* table_ = nullptr;
};

}  // namespace rt::app
