#include "homework/grader.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

namespace rt::homework {
namespace {

std::string number(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

// How far a wrong answer is from the key, in words that leave the key for the worked solution: too high or
// too low, and by how much in bands of the relative difference (a percentage to the digit would give the key
// back). An answer of zero has no relative difference: only the direction is said.
std::string howFarOff(double submitted, const Question& q) {
  const std::string direction = submitted > q.answer ? "too high" : "too low";
  if (std::abs(q.answer) <= q.tolerance) return direction;
  const double off = std::abs(submitted - q.answer) / std::abs(q.answer);
  const char* band = off < 0.01  ? "by less than 1 %"
                     : off < 0.1 ? "by 1 to 10 %"
                     : off < 0.5 ? "by 10 to 50 %"
                     : off < 1.0 ? "by 50 to 100 %"
                                 : "by more than 100 %";
  return direction + ", " + band;
}

// A wrong answer in a closed-room row: does the row still sum to 1 with the student's values? Only asked
// when the student answered every term of the row: a sum with the key's values in it would tell them.
std::string rowFeedback(const Exercise& e, const Question& q, const std::map<std::string, double>& values) {
  for (const RowCheck& r : e.rowChecks) {
    bool member = false, answered = true;
    double sum = r.known, slack = 0;
    for (const auto& [id, count] : r.terms) {
      member = member || id == q.id;
      const auto it = values.find(e.topic + "." + id);
      const Question* term = e.find(id);
      answered = answered && it != values.end();
      sum += count * (it != values.end() ? it->second : 0.0);
      slack += count * (term ? term->tolerance : 0.0);
    }
    if (member && answered && std::abs(sum - 1) > slack)
      return "; " + r.row + " of F sums to " + number(sum) +
             " with your values, not 1 (in a closed room every row of F sums to 1)";
  }
  return "";
}

}  // namespace

StudentGrade gradeStudent(const StudentExercises& key, const Submission& submission) {
  StudentGrade g;
  g.id = key.id;
  g.submission = submission;
  for (const Exercise& e : key.exercises) {
    std::vector<QuestionGrade> grades;
    for (const Question& q : e.questions) {
      QuestionGrade qg;
      qg.id = e.topic + "." + q.id;
      const auto it = submission.values.find(qg.id);
      ++g.total;
      if (it == submission.values.end()) {
        qg.feedback = "no answer";
      } else {
        qg.answered = true;
        qg.submitted = it->second;
        qg.right = std::abs(it->second - q.answer) <= q.tolerance;
        if (qg.right) {
          ++g.right;
        } else {
          // A wrong choice is neither too high nor too low: its own explanation is the feedback.
          const bool choice = !q.choices.empty();
          qg.feedback = choice ? "wrong" : "wrong: " + number(it->second) + " is " + howFarOff(it->second, q);
          for (const Mistake& m : q.mistakes)
            if (std::abs(it->second - m.value) <= q.tolerance) {
              qg.feedback += (choice ? ": " : "; likely mistake: ") + m.name;
              break;
            }
          qg.feedback += rowFeedback(e, q, submission.values);
        }
      }
      grades.push_back(std::move(qg));
    }
    g.exercises.push_back(std::move(grades));
  }
  return g;
}

std::vector<StudentGrade> gradeClass(const Assignment& key, const std::string& folder,
                                     std::vector<std::string>& unmatched) {
  std::vector<StudentGrade> grades;
  std::set<std::string> ids;
  for (const StudentExercises& s : key.students) {
    ids.insert(s.id);
    grades.push_back(gradeStudent(s, readSubmission(folder, s)));
  }
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const std::string stem = entry.path().stem().string();
    if (name == "gradebook.csv" || name == "feedback" || ids.count(entry.is_directory() ? name : stem))
      continue;
    unmatched.push_back(entry.path().string() +
                        ": matches no student of the key (expected s01.txt, s01/answers.txt, ...)");
  }
  if (ec) unmatched.push_back(folder + ": cannot list the folder: " + ec.message());
  return grades;
}

std::string gradebookCsv(const Assignment& key, const std::vector<StudentGrade>& grades) {
  std::string out = "student";
  for (const std::string& t : key.topics) out += "," + t;
  out += ",right,total,percent,status\n";
  for (const StudentGrade& g : grades) {
    out += g.id;
    for (const auto& exercise : g.exercises) {
      int right = 0;
      for (const QuestionGrade& q : exercise) right += q.right;
      out += "," + std::to_string(right) + "/" + std::to_string(exercise.size());
    }
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.1f", g.percent());
    std::string status =
        !g.submission.found() ? "missing: no submission found"
        : g.submission.problems.empty()
            ? "graded"
            : "graded with " + std::to_string(g.submission.problems.size()) + " file problem(s)";
    out +=
        "," + std::to_string(g.right) + "," + std::to_string(g.total) + "," + percent + "," + status + "\n";
  }
  return out;
}

std::string feedbackMarkdown(const StudentGrade& g) {
  char score[64];
  std::snprintf(score, sizeof score, "%d of %d right (%.1f %%)", g.right, g.total, g.percent());
  std::string out = "# Feedback for " + g.id + "\n\n" + score + ".\n\n";
  if (!g.submission.found()) out += "No submission was found.\n\n";
  for (const auto& exercise : g.exercises)
    for (const QuestionGrade& q : exercise)
      if (!q.right) out += "- `" + q.id + "`: " + q.feedback + "\n";
  if (!g.submission.problems.empty()) {
    out += "\nProblems with the files:\n\n";
    for (const std::string& p : g.submission.problems) out += "- " + p + "\n";
  }
  return out;
}

}  // namespace rt::homework
