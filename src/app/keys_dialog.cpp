#include "app/keys_dialog.h"

#include <QAction>
#include <QHeaderView>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QSet>
#include <QTableWidget>
#include <QVBoxLayout>

namespace rt::app {
namespace {

void collect(const QList<QAction*>& actions, QSet<QAction*>& seen, std::vector<KeyBinding>& out) {
  for (QAction* action : actions) {
    if (seen.contains(action)) continue;
    seen.insert(action);
    if (QMenu* menu = action->menu()) collect(menu->actions(), seen, out);
    if (action->shortcuts().isEmpty()) continue;
    QStringList keys;
    for (const QKeySequence& key : action->shortcuts()) keys << key.toString(QKeySequence::NativeText);
    QString what = action->text();
    what.remove('&');
    if (what.endsWith("...")) what.chop(3);
    out.push_back({keys.join(", "), what});
  }
}

}  // namespace

std::vector<KeyBinding> keyBindingsOf(QWidget* window) {
  std::vector<KeyBinding> out;
  QSet<QAction*> seen;
  if (auto* main = window->findChild<QMenuBar*>()) collect(main->actions(), seen, out);
  collect(window->actions(), seen, out);
  return out;
}

KeysDialog::KeysDialog(const std::vector<KeyBinding>& bindings, QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Keys"));
  setObjectName("keysDialog");
  auto* layout = new QVBoxLayout(this);
  filter_ = new QLineEdit(this);
  filter_->setObjectName("keysFilter");
  filter_->setPlaceholderText(tr("Filter: a key or a word (\"zoom\", \"Ctrl\", \"step\")"));
  filter_->setClearButtonEnabled(true);
  table_ = new QTableWidget(static_cast<int>(bindings.size()), 2, this);
  table_->setObjectName("keysTable");
  table_->setHorizontalHeaderLabels({tr("Key"), tr("What it does")});
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  for (int row = 0; row < static_cast<int>(bindings.size()); ++row) {
    table_->setItem(row, 0, new QTableWidgetItem(bindings[static_cast<std::size_t>(row)].keys));
    table_->setItem(row, 1, new QTableWidgetItem(bindings[static_cast<std::size_t>(row)].what));
  }
  layout->addWidget(filter_);
  layout->addWidget(table_, 1);
  connect(filter_, &QLineEdit::textChanged, this, &KeysDialog::applyFilter);
  resize(560, 520);
}

void KeysDialog::applyFilter(const QString& text) {
  const QString needle = text.trimmed();
  for (int row = 0; row < table_->rowCount(); ++row) {
    const bool match = needle.isEmpty() ||
                       table_->item(row, 0)->text().contains(needle, Qt::CaseInsensitive) ||
                       table_->item(row, 1)->text().contains(needle, Qt::CaseInsensitive);
    table_->setRowHidden(row, !match);
  }
}

int KeysDialog::visibleRows() const {
  int shown = 0;
  for (int row = 0; row < table_->rowCount(); ++row) shown += table_->isRowHidden(row) ? 0 : 1;
  return shown;
}

}  // namespace rt::app
