#include "app/exercise_panel.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QVBoxLayout>

#include "homework/grader.h"

namespace rt::app {
namespace {

// Labels are Markdown with $...$ maths: a plain label shows them without dollars, braces and backslashes
// (F_{12} reads F_12).
QString plain(const std::string& label) {
  QString text = QString::fromStdString(label);
  text.remove('$');
  text.remove('{');
  text.remove('}');
  return text.replace("\\", "");
}

QString settingsKey(const QString& place) {
  return "exercises/" + place;
}

// The exercise a kept entry belongs to: a lesson edited to another topic or seed leaves old answers unused.
QString identity(const homework::Exercise& e) {
  return QString::fromStdString(e.topic) + "#" + QString::number(e.seed);
}

}  // namespace

ExercisePanel::ExercisePanel(QWidget* parent) : QWidget(parent) {
  setObjectName("exercisePanel");
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  fields_ = new QWidget(scroll);
  // A grid, not a QFormLayout: Qt 6.4's form layout writes past a buffer when it lays out hidden rows (this
  // panel is hidden on every step that is not an exercise), which corrupted the heap.
  form_ = new QGridLayout(fields_);
  form_->setColumnStretch(1, 1);
  scroll->setWidget(fields_);

  auto* buttons = new QHBoxLayout();
  check_ = new QPushButton(tr("Check"), this);
  check_->setObjectName("checkAnswers");
  auto* hint = new QPushButton(tr("Hint"), this);
  hint->setObjectName("showHint");
  auto* solution = new QPushButton(tr("Show solution"), this);
  solution->setObjectName("showSolution");
  buttons->addWidget(check_);
  buttons->addWidget(hint);
  buttons->addWidget(solution);
  summary_ = new QLabel(this);
  summary_->setObjectName("exerciseSummary");
  summary_->setWordWrap(true);
  layout->addWidget(scroll);
  layout->addLayout(buttons);
  layout->addWidget(summary_);
  connect(check_, &QPushButton::clicked, this, &ExercisePanel::check);
  connect(hint, &QPushButton::clicked, this, &ExercisePanel::showHint);
  connect(solution, &QPushButton::clicked, this, &ExercisePanel::showSolution);
  hide();
}

void ExercisePanel::setExercise(const std::optional<homework::Exercise>& exercise, const QString& place) {
  const bool same = exercise && exercise_ && exercise->topic == exercise_->topic &&
                    exercise->seed == exercise_->seed && place == place_;
  if (same) return;
  exercise_ = exercise;
  place_ = place;
  checked_ = false;
  while (QLayoutItem* item = form_->takeAt(0)) {
    delete item->widget();
    delete item;
  }
  edits_.clear();
  verdicts_.clear();
  summary_->clear();
  notes_.clear();
  setVisible(exercise_.has_value());
  if (!exercise_) return;
  int line = 0;
  for (const homework::Question& q : exercise_->questions) {
    auto* row = new QWidget(fields_);
    auto* rowLayout = new QHBoxLayout(row);
    rowLayout->setContentsMargins(0, 0, 0, 0);
    auto* edit = new QLineEdit(row);
    edit->setObjectName(QString::fromStdString("answer-" + q.id));
    edit->setPlaceholderText(q.integer ? tr("whole number") : tr("number"));
    auto* verdict = new QLabel(row);
    verdict->setWordWrap(true);
    rowLayout->addWidget(edit);
    rowLayout->addWidget(verdict, 1);
    auto* label = new QLabel(plain(q.label), fields_);
    label->setWordWrap(true);
    form_->addWidget(label, line, 0);
    form_->addWidget(row, line++, 1);
    edits_[q.id] = edit;
    verdicts_[q.id] = verdict;
    // Enter in a field checks, as the button does.
    connect(edit, &QLineEdit::returnPressed, this, &ExercisePanel::check);
    connect(edit, &QLineEdit::textEdited, this, &ExercisePanel::keepAnswers);
  }
  // The fields at the top, the free space below them (the grid remembers stretches of earlier rows).
  for (int r = 0; r < form_->rowCount(); ++r) form_->setRowStretch(r, r == line ? 1 : 0);
  if (line >= form_->rowCount()) form_->setRowStretch(line, 1);
  restoreAnswers();
}

void ExercisePanel::keepAnswers() const {
  if (!exercise_ || place_.isEmpty()) return;
  QVariantMap answers;
  for (const auto& [id, edit] : edits_)
    if (!edit->text().isEmpty()) answers[QString::fromStdString(id)] = edit->text();
  QVariantMap kept;
  kept["exercise"] = identity(*exercise_);
  kept["answers"] = answers;
  kept["checked"] = checked_;
  QSettings().setValue(settingsKey(place_), kept);
}

void ExercisePanel::restoreAnswers() {
  if (!exercise_ || place_.isEmpty()) return;
  const QVariantMap kept = QSettings().value(settingsKey(place_)).toMap();
  if (kept.value("exercise").toString() != identity(*exercise_)) return;
  const QVariantMap answers = kept.value("answers").toMap();
  for (const auto& [id, edit] : edits_) edit->setText(answers.value(QString::fromStdString(id)).toString());
  if (kept.value("checked").toBool()) check();
}

QLineEdit* ExercisePanel::field(const std::string& id) const {
  const auto it = edits_.find(id);
  return it == edits_.end() ? nullptr : it->second;
}

QString ExercisePanel::verdict(const std::string& id) const {
  const auto it = verdicts_.find(id);
  return it == verdicts_.end() ? QString() : it->second->text();
}

QString ExercisePanel::summary() const {
  return summary_->text();
}

void ExercisePanel::check() {
  if (!exercise_) return;
  homework::Submission submission;
  submission.files.push_back("app");
  std::vector<std::string> unreadable;
  for (const homework::Question& q : exercise_->questions) {
    const QString text = edits_[q.id]->text().trimmed();
    if (text.isEmpty()) continue;
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (ok)
      submission.values[exercise_->topic + "." + q.id] = value;
    else
      unreadable.push_back(q.id);
  }
  const homework::StudentGrade grade =
      homework::gradeStudent(homework::StudentExercises{"reader", {*exercise_}}, submission);
  const auto& grades = grade.exercises.front();
  for (std::size_t k = 0; k < grades.size(); ++k) {
    const std::string& id = exercise_->questions[k].id;
    QLabel* label = verdicts_[id];
    if (std::find(unreadable.begin(), unreadable.end(), id) != unreadable.end())
      label->setText(tr("not a number"));
    else if (!grades[k].answered)
      label->setText(QString());
    else
      label->setText(grades[k].right ? tr("right") : QString::fromStdString(grades[k].feedback));
  }
  summary_->setText(tr("%1 of %2 right").arg(grade.right).arg(grade.total));
  checked_ = true;
  keepAnswers();
}

void ExercisePanel::showHint() {
  if (!exercise_) return;
  notes_ = tr("### Hint\n\n") + QString::fromStdString(exercise_->hint) + "\n";
  emit notesRequested(notes_);
}

void ExercisePanel::showSolution() {
  if (!exercise_) return;
  notes_ = tr("### Worked solution\n\n");
  for (const std::string& step : exercise_->solution) notes_ += "- " + QString::fromStdString(step) + "\n";
  emit notesRequested(notes_);
}

}  // namespace rt::app
