// The reader's side of an exercise step: one input field per question (a radio button per choice for a
// conceptual question), Check (the grader of the homework library, so the app names the same slips as
// `radiosity homework check`, and a wrong choice's own explanation), a hint and the worked solution. A line
// above the fields says how to answer, so that the lessons need not.
// The hint and the solution are Markdown with maths: the window shows them under the step's text, where
// KaTeX sets them as it sets the lesson. Hidden for every other step. What the reader typed, and whether
// Check was pressed, is kept per step in the settings: it is there again after leaving the step, and after
// a restart.
#pragma once

#include <QWidget>
#include <map>
#include <optional>

#include "homework/exercise.h"

class QLabel;
class QLineEdit;
class QPushButton;
class QButtonGroup;
class QRadioButton;
class QGridLayout;

namespace rt::app {

class ExercisePanel : public QWidget {
  Q_OBJECT
 public:
  explicit ExercisePanel(QWidget* parent = nullptr);
  // Shows the fields of `exercise` (empty: hides the panel) with the answers kept under `place` (the lesson
  // and step, e.g. "cornell-box/4"; empty: none kept) for this exercise. The same exercise again keeps what
  // was typed.
  void setExercise(const std::optional<homework::Exercise>& exercise, const QString& place = QString());
  const std::optional<homework::Exercise>& exercise() const { return exercise_; }

  QLineEdit* field(const std::string& questionId) const;
  // The radio button of a conceptual question's choice `index` (1-based); null when there is none.
  QRadioButton* choice(int index) const;
  // The text shown beside that button (plain: maths as Unicode).
  QString choiceText(int index) const;
  // The line that says how to answer.
  QString instruction() const;
  // What Check said about a question ("right", or the feedback naming the slip); empty before Check.
  QString verdict(const std::string& questionId) const;
  QString summary() const;
  // The hint or solution last asked for (Markdown with $...$ maths); empty for a new exercise.
  const QString& notes() const { return notes_; }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 signals:
  // Hint or Show solution was pressed: `markdown` goes under the step's text.
  void notesRequested(const QString& markdown);

 public slots:
  void check();
  void showHint();
  void showSolution();

 private:
  std::optional<homework::Exercise> exercise_;
  QGridLayout* form_ = nullptr;
  QWidget* fields_ = nullptr;
  std::map<std::string, QLineEdit*> edits_;
  std::map<std::string, QLabel*> verdicts_;
  QButtonGroup* choices_ = nullptr;  // the conceptual question's choices, ids 1..n
  std::string choiceQuestion_;       // its question id
  QLabel* instruction_ = nullptr;
  // The answers typed and whether they were checked, kept under place_ for this exercise only.
  void keepAnswers() const;
  void restoreAnswers();
  // The choices from grid row `line` on, one a row, then the verdict; returns the next free row.
  int addChoices(const homework::Question& q, int line);
  std::map<QObject*, QRadioButton*> choiceTexts_;  // each choice's text label and its button

  QLabel* summary_ = nullptr;
  QString notes_;
  QString place_;
  bool checked_ = false;
  QPushButton* check_ = nullptr;
};

}  // namespace rt::app
