#include "app/exercise_panel.h"

#include <QButtonGroup>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QSettings>
#include <QVBoxLayout>

#include "homework/conceptual.h"
#include "homework/grader.h"
#include "homework/plain_text.h"

namespace rt::app {
namespace {

// Labels, choices and verdicts are Markdown with $...$ maths: a plain label shows them as plain text
// (F_{12} reads F_12, \rho reads ρ).
QString plain(const std::string& label) {
  return QString::fromStdString(homework::plainText(label));
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
  instruction_ = new QLabel(this);
  instruction_->setObjectName("exerciseInstruction");
  instruction_->setWordWrap(true);
  layout->addWidget(instruction_);
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
  delete choices_;
  choices_ = nullptr;
  choiceTexts_.clear();
  choiceQuestion_.clear();
  summary_->clear();
  notes_.clear();
  setVisible(exercise_.has_value());
  if (!exercise_) return;
  instruction_->setText(
      QString::fromStdString(homework::answerInstruction(*exercise_, homework::Frame::App)));
  int line = 0;
  for (const homework::Question& q : exercise_->questions) {
    if (!q.choices.empty()) {
      line = addChoices(q, line);
      continue;
    }
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

int ExercisePanel::addChoices(const homework::Question& q, int line) {
  choices_ = new QButtonGroup(this);
  choiceQuestion_ = q.id;
  // One grid row per choice: the button with its letter, the choice's text wrapped beside it (a radio
  // button's own text does not wrap). A click on the text picks the choice too (eventFilter).
  for (std::size_t k = 0; k < q.choices.size(); ++k) {
    auto* button = new QRadioButton(QString::fromStdString(homework::choiceLetter(k)), fields_);
    button->setObjectName(QString("choice-%1").arg(k + 1));
    auto* text = new QLabel(plain(q.choices[k]), fields_);
    text->setWordWrap(true);
    text->installEventFilter(this);
    choiceTexts_[text] = button;
    choices_->addButton(button, static_cast<int>(k + 1));
    form_->addWidget(button, line, 0, Qt::AlignTop);
    form_->addWidget(text, line++, 1);
    connect(button, &QRadioButton::toggled, this, &ExercisePanel::keepAnswers);
  }
  auto* verdict = new QLabel(fields_);
  verdict->setWordWrap(true);
  form_->addWidget(verdict, line++, 0, 1, 2);
  verdicts_[q.id] = verdict;
  return line;
}

bool ExercisePanel::eventFilter(QObject* watched, QEvent* event) {
  const auto it = choiceTexts_.find(watched);
  if (it != choiceTexts_.end() && event->type() == QEvent::MouseButtonRelease) {
    it->second->click();
    return true;
  }
  return QWidget::eventFilter(watched, event);
}

QString ExercisePanel::choiceText(int index) const {
  for (const auto& [text, button] : choiceTexts_)
    if (choices_ && choices_->id(button) == index) return static_cast<QLabel*>(text)->text();
  return QString();
}

QRadioButton* ExercisePanel::choice(int index) const {
  return choices_ ? qobject_cast<QRadioButton*>(choices_->button(index)) : nullptr;
}

QString ExercisePanel::instruction() const {
  return instruction_->text();
}

void ExercisePanel::keepAnswers() const {
  if (!exercise_ || place_.isEmpty()) return;
  QVariantMap answers;
  for (const auto& [id, edit] : edits_)
    if (!edit->text().isEmpty()) answers[QString::fromStdString(id)] = edit->text();
  if (choices_ && choices_->checkedId() > 0)
    answers[QString::fromStdString(choiceQuestion_)] = choices_->checkedId();
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
  if (choices_)
    if (QAbstractButton* chosen =
            choices_->button(answers.value(QString::fromStdString(choiceQuestion_)).toInt()))
      chosen->setChecked(true);
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
    if (q.id == choiceQuestion_) {
      if (choices_->checkedId() > 0) submission.values[exercise_->topic + "." + q.id] = choices_->checkedId();
      continue;
    }
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
      label->setText(grades[k].right ? tr("right") : plain(grades[k].feedback));
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
