// The grader: the key handed in as a submission scores 100 %, one entry pushed past its tolerance loses
// exactly that question, every slip the key recognises is named, and malformed or missing submissions are
// reported per file while the rest of the class is graded.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.h"
#include "core/io/matrix_export.h"
#include "homework/conceptual.h"
#include "homework/grader.h"
#include "homework/handout.h"
#include "homework/plain_text.h"
#include "homework/topic_table.h"
#include "support/test_paths.h"

namespace rt::homework {
namespace {

// The key through key.json, as `homework check` reads it.
Assignment classOf(int count, std::uint64_t seed) {
  const Assignment a = makeAssignment(topicIds(), seed, count);
  return parseKeyJson(keyJson(a), "key.json");
}

Submission answersOf(const StudentExercises& s) {
  Submission sub;
  sub.files.push_back("memory");
  readAnswerText(answersText(s, true), "memory", false, s, sub);
  return sub;
}

TEST(HomeworkGrader, KeyAsSubmissionScoresFull) {
  const Assignment a = classOf(10, 3);
  for (const StudentExercises& s : a.students) {
    const Submission sub = answersOf(s);
    EXPECT_TRUE(sub.problems.empty()) << sub.problems.front();
    const StudentGrade g = gradeStudent(s, sub);
    EXPECT_EQ(g.right, g.total) << s.id;
    EXPECT_DOUBLE_EQ(g.percent(), 100.0);
  }
}

TEST(HomeworkGrader, OneEntryPastItsToleranceLosesExactlyThatQuestion) {
  const Assignment a = classOf(3, 11);
  for (const StudentExercises& s : a.students)
    for (const Exercise& e : s.exercises)
      for (const Question& q : e.questions) {
        Submission sub = answersOf(s);
        sub.values[e.topic + "." + q.id] = q.answer + 3 * q.tolerance + (q.integer ? 1 : 0);
        const StudentGrade g = gradeStudent(s, sub);
        EXPECT_EQ(g.right, g.total - 1) << s.id << " " << e.topic << "." << q.id;
        for (const auto& exercise : g.exercises)
          for (const QuestionGrade& qg : exercise)
            EXPECT_EQ(qg.right, qg.id != e.topic + "." + q.id) << qg.id;
      }
}

// Submits `value` for one question of the first variant (over seeds) that recognises `mistake`, and returns
// the feedback.
std::string feedbackFor(const std::string& topic, const std::string& mistake) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const Assignment a = parseKeyJson(keyJson(makeAssignment({topic}, seed, 1)), "key.json");
    const StudentExercises& s = a.students[0];
    for (const Question& q : s.exercises[0].questions)
      for (const Mistake& m : q.mistakes)
        if (m.name.find(mistake) != std::string::npos) {
          Submission sub = answersOf(s);
          sub.values[topic + "." + q.id] = m.value;
          const StudentGrade g = gradeStudent(s, sub);
          for (const QuestionGrade& qg : g.exercises[0])
            if (!qg.right) return qg.feedback;
        }
  }
  return "no variant recognises '" + mistake + "'";
}

TEST(HomeworkGrader, RecognisedMistakesAreNamed) {
  EXPECT_NE(feedbackFor("rectangles", "F_21 given for F_12").find("likely mistake: F_21 given for F_12"),
            std::string::npos);
  EXPECT_NE(feedbackFor("jacobi-gauss-seidel", "Gauss-Seidel step done as Jacobi")
                .find("likely mistake: Gauss-Seidel step done as Jacobi"),
            std::string::npos);
  EXPECT_NE(feedbackFor("tone-mapping", "gamma applied twice").find("likely mistake: gamma applied twice"),
            std::string::npos);
  const std::string row = feedbackFor("closure", "symmetry forgotten");
  EXPECT_NE(row.find("row 1 (the floor) of F sums to"), std::string::npos) << row;
  EXPECT_NE(row.find("not 1"), std::string::npos) << row;
  // Every slip of every topic is named when its value is handed in.
  for (const Topic& t : topicTable()) {
    const Assignment a = parseKeyJson(keyJson(makeAssignment({t.id}, 5, 1)), "key.json");
    const StudentExercises& s = a.students[0];
    for (const Question& q : s.exercises[0].questions)
      for (const Mistake& m : q.mistakes) {
        Submission sub = answersOf(s);
        sub.values[std::string(t.id) + "." + q.id] = m.value;
        const StudentGrade g = gradeStudent(s, sub);
        bool named = false;
        for (const QuestionGrade& qg : g.exercises[0])
          named = named || qg.feedback.find(m.name) != std::string::npos;
        EXPECT_TRUE(named) << t.id << "." << q.id << ": " << m.name;
      }
  }
}

// The student reads the feedback before asking for the worked solution: a wrong answer is told too high or
// too low and by about how much, never the key's value or its tolerance.
TEST(HomeworkGrader, FeedbackSaysHowFarOffButNotTheKey) {
  for (const Topic& t : topicTable()) {
    const Assignment a = parseKeyJson(keyJson(makeAssignment({t.id}, 7, 1)), "key.json");
    const StudentExercises& s = a.students[0];
    for (const Question& q : s.exercises[0].questions) {
      for (const double factor : {0.95, 1.3, 3.0}) {
        Submission sub = answersOf(s);
        const double wrong =
            q.answer == 0 ? q.tolerance * 10 * factor : q.answer * factor + (q.integer ? 1 : 0);
        sub.values[std::string(t.id) + "." + q.id] = wrong;
        const StudentGrade g = gradeStudent(s, sub);
        for (const QuestionGrade& qg : g.exercises[0]) {
          if (qg.right) continue;
          SCOPED_TRACE(qg.id + ": " + qg.feedback);
          // The student's value, the direction, the band; then what the slips and the row checks say.
          static const std::regex shape(
              "wrong: \\S+ is too (high|low)(, by (less than 1|1 to 10|10 to 50|50 to 100|more than 100) "
              "%)?(; .*)?");
          EXPECT_TRUE(std::regex_match(qg.feedback, shape));
          EXPECT_EQ(qg.feedback.find("key"), std::string::npos);
          EXPECT_EQ(qg.feedback.find("+-"), std::string::npos);
          EXPECT_NE(qg.feedback.find(wrong > q.answer ? "too high" : "too low"), std::string::npos);
        }
      }
    }
  }
}

TEST(HomeworkGrader, FeedbackNamesTheBandOfTheRelativeDifference) {
  const Assignment a = parseKeyJson(keyJson(makeAssignment({"rectangles"}, 3, 1)), "key.json");
  const StudentExercises& s = a.students[0];
  const Question& q = s.exercises[0].questions[0];
  ASSERT_GT(q.answer, 0);
  const std::pair<double, const char*> cases[] = {{0.95, "too low, by 1 to 10 %"},
                                                  {1.3, "too high, by 10 to 50 %"},
                                                  {0.4, "too low, by 50 to 100 %"},
                                                  {2.5, "too high, by more than 100 %"}};
  for (const auto& [factor, words] : cases) {
    Submission sub = answersOf(s);
    sub.values["rectangles." + q.id] = q.answer * factor;
    const std::string feedback = gradeStudent(s, sub).exercises[0][0].feedback;
    EXPECT_NE(feedback.find(words), std::string::npos) << factor << ": " << feedback;
  }
}

void write(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

TEST(HomeworkGrader, MalformedAndMissingSubmissionsAreReportedAndTheRestGraded) {
  const Assignment a = classOf(7, 21);
  const std::string dir = test::scratchDir("homework-grader");
  // s01: the key, plain text. s02: the key as CSV, one line broken and one unknown id.
  write(dir + "/s01.txt", answersText(a.students[0], true));
  std::string csv = "question,value\n";
  for (const Exercise& e : a.students[1].exercises)
    for (const Question& q : e.questions) csv += e.topic + "." + q.id + "," + std::to_string(q.answer) + "\n";
  csv += "rectangles.F12 0.5\nno-such.question,1\n";
  write(dir + "/s02.csv", csv);
  // s03: binary garbage. s04: nothing. s05: an NPY with the wrong count. s06: NPY vectors (1-D, as
  // numpy.save).
  write(dir + "/s03/answers.txt", std::string("\x89PNG\0\0\x01", 7));
  Eigen::MatrixXd three(1, 3);
  three << 1, 2, 3;
  std::filesystem::create_directories(dir + "/s05");
  writeMatrix(three, dir + "/s05/rectangles.npy");
  for (const Exercise& e : a.students[5].exercises) {
    std::string body;
    for (const Question& q : e.questions)
      body.append(reinterpret_cast<const char*>(&q.answer), sizeof(double));
    std::string header =
        "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(e.questions.size()) + ",), }";
    header.append(64 - (10 + header.size() + 1) % 64, ' ');
    header += '\n';
    const auto length = static_cast<std::uint16_t>(header.size());
    write(dir + "/s06/" + e.topic + ".npy", std::string("\x93NUMPY\x01\x00", 8) +
                                                std::string(reinterpret_cast<const char*>(&length), 2) +
                                                header + body);
  }
  write(dir + "/stray.txt", "rectangles.F12 = 1\n");
  std::vector<std::string> unmatched;
  const auto grades = gradeClass(a, dir, unmatched);
  ASSERT_EQ(grades.size(), 7u);
  EXPECT_EQ(grades[0].right, grades[0].total);
  EXPECT_EQ(grades[1].right, grades[1].total);  // the broken lines are reported, the rest is graded
  ASSERT_EQ(grades[1].submission.problems.size(), 2u);
  EXPECT_NE(grades[1].submission.problems[0].find("s02.csv:"), std::string::npos);
  EXPECT_NE(grades[1].submission.problems[0].find("expected `question , number`"), std::string::npos);
  EXPECT_NE(grades[1].submission.problems[1].find("unknown question 'no-such.question'"), std::string::npos);
  ASSERT_EQ(grades[2].submission.problems.size(), 1u);
  EXPECT_NE(grades[2].submission.problems[0].find("not a text file"), std::string::npos);
  EXPECT_EQ(grades[2].right, 0);
  EXPECT_FALSE(grades[3].submission.found());
  ASSERT_EQ(grades[4].submission.problems.size(), 1u);
  EXPECT_NE(grades[4].submission.problems[0].find("3 numbers, but rectangles has 2 questions"),
            std::string::npos)
      << grades[4].submission.problems[0];
  EXPECT_EQ(grades[5].right, grades[5].total)
      << (grades[5].submission.problems.empty() ? "" : grades[5].submission.problems[0]);
  ASSERT_EQ(unmatched.size(), 1u);
  EXPECT_NE(unmatched[0].find("stray.txt"), std::string::npos);
  const std::string book = gradebookCsv(a, grades);
  EXPECT_EQ(book.rfind("student,rectangles,", 0), 0u);
  EXPECT_NE(book.find("s04,"), std::string::npos);
  EXPECT_NE(book.find("missing: no submission found"), std::string::npos);
  EXPECT_NE(book.find("graded with 2 file problem(s)"), std::string::npos);
  EXPECT_NE(feedbackMarkdown(grades[3]).find("No submission was found."), std::string::npos);
}

TEST(HomeworkGrader, AMalformedKeyIsAnInputErrorNamingTheFile) {
  for (const char* text :
       {"{", "[1e2965]", "{\"format\": 5}",
        "{\"format\": \"radiosity homework key\", \"seed\": 1, \"topics\": [], \"students\": "
        "[{\"id\": \"s01\", \"exercises\": [{\"topic\": \"x\", \"title\": 5, \"questions\": []}]}]}"}) {
    try {
      parseKeyJson(text, "bad-key.json");
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bad-key.json"), std::string::npos) << e.what();
    }
  }
}

// A conceptual question: the right choice scores, a wrong one is said wrong with its own explanation (never
// too high or too low), and the book prints the choices with letters and the answer in the appendix.
TEST(HomeworkGrader, AWrongChoiceIsExplainedByItsOwnExplanation) {
  const Exercise e =
      conceptualExercise("Q", {{"Twice", "The error falls like one over the root of N.", false},
                               {"Four times", "Halving 1/sqrt(N) needs N four times larger.", true},
                               {"Never", "Monte Carlo error falls with the samples.", false}});
  ASSERT_TRUE(exerciseProblems(e).empty()) << exerciseProblems(e).front();
  const StudentExercises key{"reader", {e}};
  auto grade = [&](double choice) {
    Submission sub;
    sub.files.push_back("app");
    sub.values["conceptual.choice"] = choice;
    return gradeStudent(key, sub).exercises.front().front();
  };
  EXPECT_TRUE(grade(2).right);
  EXPECT_EQ(grade(1).feedback, "wrong: The error falls like one over the root of N.");
  EXPECT_EQ(grade(3).feedback, "wrong: Monte Carlo error falls with the samples.");
  const std::string book = exerciseBookText(e);
  EXPECT_NE(book.find("- (a) Twice\n- (b) Four times\n- (c) Never"), std::string::npos) << book;
  const std::string answers = answersAppendix({{"Q", e}});
  EXPECT_NE(answers.find("- (b) Four times"), std::string::npos) << answers;
  EXPECT_NE(answers.find("- Not (a) Twice. The error falls"), std::string::npos) << answers;
  EXPECT_NE(answers.find("- The answer is (b) Four times. Halving"), std::string::npos) << answers;
}

// A numeric answer is printed as a number whatever its sign: -1 is not "the choice before the first".
TEST(HomeworkAnswers, ANegativeNumericAnswerIsPrintedAsANumber) {
  Exercise e;
  e.statement = "How much?";
  Question q;
  q.label = "the change";
  q.answer = -1;
  e.questions.push_back(q);
  const std::string answers = answersAppendix({{"Q", e}});
  EXPECT_NE(answers.find("- the change: $-1$"), std::string::npos) << answers;
}

TEST(HomeworkPlainText, MathsBecomesUnicodeForWidgets) {
  EXPECT_EQ(plainText("$\\rho_i F_{ij} \\le 1$"), "ρ_i F_ij ≤ 1");
  EXPECT_EQ(plainText("$\\operatorname{diag}(\\rho)F$ and $s/\\sqrt N$"), "diag(ρ)F and s/√N");
  EXPECT_EQ(plainText("$\\cos\\theta\\,d\\omega$"), "cosθ dω");
  EXPECT_EQ(plainText("F_ji given for F_ij"), "F_ji given for F_ij");
}

}  // namespace
}  // namespace rt::homework
