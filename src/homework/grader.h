// Grading a class against the key: each question is right within its tolerance; a wrong answer is compared
// with the slips the key recognises (F_ji for F_ij, Gauss-Seidel done as Jacobi, gamma applied twice...) and
// with the closed-room rows it belongs to, so the feedback can name the likely mistake. Missing or malformed
// submissions are reported per file and the rest of the class is graded.
#pragma once

#include <string>
#include <vector>

#include "homework/answer_key.h"
#include "homework/submission.h"

namespace rt::homework {

struct QuestionGrade {
  std::string id;  // "topic.question"
  bool answered = false, right = false;
  double submitted = 0;
  std::string feedback;  // empty when right; never the key's value (the student reads it before the solution)
};

struct StudentGrade {
  std::string id;
  Submission submission;
  std::vector<std::vector<QuestionGrade>> exercises;  // parallel to the key's exercises
  int right = 0, total = 0;
  double percent() const { return total ? 100.0 * right / total : 0.0; }
};

StudentGrade gradeStudent(const StudentExercises& key, const Submission& submission);
// Every student of the key from the files under `folder`; `unmatched` receives the files that belong to no
// student of the key.
std::vector<StudentGrade> gradeClass(const Assignment& key, const std::string& folder,
                                     std::vector<std::string>& unmatched);

// One row per student: points per topic, total, percent and the status of the submission.
std::string gradebookCsv(const Assignment& key, const std::vector<StudentGrade>& grades);
// What a student reads: score, then every wrong or missing answer with the named mistake, then file problems.
std::string feedbackMarkdown(const StudentGrade& grade);

}  // namespace rt::homework
