// Exercise steps: every shipped lesson ends with its exercises, at least two numeric ones whose topics fit
// the lesson (the topic table's row lists it: the one place that says which topics fit a lesson) and at least
// one conceptual question; each runs without a scene into a question with its key. An exercise step without a
// topic or question, and every malformed ```question block, is an error at its line.
#include <gtest/gtest.h>

#include <set>
#include <tuple>
#include <vector>

#include "core/input_error.h"
#include "homework/conceptual.h"
#include "homework/topic_table.h"
#include "lesson/exercise_topics.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_runner.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

TEST(ExerciseSteps, EveryLessonEndsWithExercisesOnItsOwnTopic) {
  const auto folders = test::repoFolders();
  StepRunner runner(folders.scenes);
  for (const Lesson& lesson : loadCatalogue(folders)) {
    SCOPED_TRACE(lesson.id);
    std::size_t first = lesson.steps.size();
    while (first > 0 && lesson.steps[first - 1].stage == Stage::Exercise) --first;
    int numeric = 0, conceptual = 0;
    for (std::size_t k = 0; k < first; ++k)
      EXPECT_NE(lesson.steps[k].stage, Stage::Exercise) << "exercises come last: " << lesson.steps[k].title;
    for (std::size_t k = first; k < lesson.steps.size(); ++k) {
      const Step& step = lesson.steps[k];
      SCOPED_TRACE(step.title);
      const StepResult result = runner.run(lesson, step);
      ASSERT_TRUE(result.exercise.has_value());
      ASSERT_FALSE(result.exercise->questions.empty());
      const auto& q = result.exercise->questions.front();
      EXPECT_EQ(result.value("answer." + q.id), q.answer);
      EXPECT_NO_THROW(resolvedText(lesson, step, result));
      if (!step.choices.empty()) {
        ++conceptual;
        EXPECT_EQ(q.choices.size(), step.choices.size());
        EXPECT_EQ(q.mistakes.size(), step.choices.size() - 1) << "every wrong choice is explained";
        for (const homework::Choice& c : step.choices)
          EXPECT_GE(c.because.size(), 20u) << "an explanation, not a word: " << c.text;
        continue;
      }
      ++numeric;
      const homework::Topic* topic = homework::findTopic(step.parameters.topic);
      ASSERT_NE(topic, nullptr);
      EXPECT_TRUE(homework::topicFitsLesson(*topic, lesson.id))
          << "topic " << topic->id << " does not practise " << lesson.id << " (its row lists "
          << topic->lessons << "): choose a topic whose row lists the lesson";
      EXPECT_TRUE(exerciseTopicProblems(lesson).empty()) << exerciseTopicProblems(lesson).front();
      EXPECT_EQ(result.exercise->seed, step.parameters.seed.value_or(1));
    }
    EXPECT_GE(numeric, 2) << "two numeric exercises";
    EXPECT_GE(conceptual, 1) << "a conceptual question";
  }
}

// How to answer is the exercise frame's line (homework::answerInstruction, under every exercise in the app
// and the book): no lesson says it again in its own words.
TEST(ExerciseSteps, NoLessonRepeatsTheFramesInstruction) {
  homework::Exercise numeric, choice;
  numeric.questions.resize(1);
  choice.questions.resize(1);
  choice.questions[0].choices = {"a", "b"};
  std::vector<std::string> clauses;
  for (const homework::Exercise* e : {&numeric, &choice})
    for (const homework::Frame frame : {homework::Frame::App, homework::Frame::Book}) {
      std::string line = homework::answerInstruction(*e, frame);
      for (std::size_t at = line.find_first_of(";,."); !line.empty(); at = line.find_first_of(";,.")) {
        std::string clause = line.substr(0, at);
        while (!clause.empty() && (clause.front() == ' ' || clause.front() == '*')) clause.erase(0, 1);
        if (clause.size() > 12) clauses.push_back(clause);
        line = at == std::string::npos ? "" : line.substr(at + 1);
      }
    }
  ASSERT_GE(clauses.size(), 4u);
  for (const Lesson& lesson : loadCatalogue(test::repoFolders()))
    for (const Step& step : lesson.steps) {
      std::string text = step.text;
      for (char& c : text)
        if (c == '\n') c = ' ';
      for (const std::string& clause : clauses)
        EXPECT_EQ(text.find(clause), std::string::npos)
            << lesson.file << ": the step '" << step.title << "' repeats the exercise frame's '" << clause
            << "'";
    }
}

TEST(ExerciseSteps, EveryLessonATopicListsExistsAndHasATopic) {
  const auto folders = test::repoFolders();
  std::set<std::string> ids;
  for (const Lesson& lesson : loadCatalogue(folders)) ids.insert(lesson.id);
  std::set<std::string> covered;
  for (const homework::Topic& t : homework::topicTable()) {
    std::string list = std::string(t.lessons) + ",";
    for (auto at = list.find(','); at != std::string::npos; list.erase(0, at + 1), at = list.find(',')) {
      const std::string id = list.substr(0, at);
      EXPECT_TRUE(ids.count(id)) << "topic " << t.id << " lists '" << id << "', which is no lesson";
      covered.insert(id);
    }
  }
  for (const std::string& id : ids) EXPECT_TRUE(covered.count(id)) << "no topic practises " << id;
}

TEST(ExerciseSteps, LessonCheckNamesATopicThatDoesNotFitItsLesson) {
  const Lesson lesson = parseLesson(
      "---\ntitle: T\norder: 1\n---\n\n## Q\n\n```step\nstage: exercise\ntopic: southwell\nseed: "
      "3\n```\n\nText.\n",
      "measuring-light", "measuring-light.md");
  const auto problems = exerciseTopicProblems(lesson);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("measuring-light.md:10: topic 'southwell' does not practise"), std::string::npos)
      << problems[0];
  EXPECT_NE(problems[0].find("topics that do: irradiance"), std::string::npos) << problems[0];
}

TEST(ExerciseSteps, AnExerciseNeedsATopicAndNoScene) {
  const std::string text =
      "---\ntitle: T\norder: 1\n---\n\n## Q\n\n```step\nstage: exercise\nseed: 3\n```\n\nText.\n";
  try {
    parseLesson(text, "ex", "ex.md");
    FAIL() << "accepted an exercise without a topic";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ex.md:9"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("needs a 'topic'"), std::string::npos) << e.what();
  }
  const Lesson ok = parseLesson(
      "---\ntitle: T\norder: 1\n---\n\n## Q\n\n```step\nstage: exercise\ntopic: southwell\nseed: 3\n```\n\n"
      "Shot {{answer.shooter1:int}} first.\n",
      "ok", "ok.md");
  StepRunner runner(test::repoFolders().scenes);
  const StepResult r = runner.run(ok, ok.steps[0]);
  EXPECT_NE(resolvedText(ok, ok.steps[0], r).find("Shot "), std::string::npos);
}

const char* kQuestionLesson =
    "---\ntitle: T\norder: 1\n---\n\n## Why?\n\n```step\nstage: exercise\n```\n\n"  // lines 1-10
    "Why is the sky blue?\n\n"                                                      // 12
    "```question\n"                                                                 // 14
    "wrong: Because the sea\n"                                                      // 15
    "  reflects it.\n"                                                              // 16
    "because: The sky is blue over deserts too.\n"                                  // 17
    "right: Rayleigh scattering.\n"                                                 // 18
    "because: Short wavelengths scatter most, as $1/\\lambda^4$.\n"                 // 19
    "```\n\n"                                                                       // 20
    "After the question, {{answer.choice:int}}.\n";                                 // 22

TEST(ExerciseSteps, AConceptualQuestionIsParsedIntoChoicesWithExplanations) {
  const Lesson lesson = parseLesson(kQuestionLesson, "q", "q.md");
  ASSERT_EQ(lesson.steps.size(), 1u);
  const Step& step = lesson.steps[0];
  EXPECT_EQ(step.questionLine, 14);
  ASSERT_EQ(step.choices.size(), 2u);
  EXPECT_EQ(step.choices[0].text, "Because the sea reflects it.");
  EXPECT_FALSE(step.choices[0].right);
  EXPECT_TRUE(step.choices[1].right);
  EXPECT_EQ(step.text.find("```"), std::string::npos) << "the block is not part of the text";
  StepRunner runner(test::repoFolders().scenes);
  const StepResult r = runner.run(lesson, step);
  ASSERT_TRUE(r.exercise.has_value());
  const homework::Question& q = r.exercise->questions.front();
  EXPECT_EQ(q.answer, 2);
  ASSERT_EQ(q.mistakes.size(), 1u);
  EXPECT_EQ(q.mistakes[0].name, "The sky is blue over deserts too.");
  EXPECT_NE(resolvedText(lesson, step, r).find("After the question, 2."), std::string::npos);
}

TEST(ExerciseSteps, AMalformedQuestionBlockIsAnErrorAtItsLine) {
  const std::string good = kQuestionLesson;
  const std::vector<std::tuple<std::string, std::string, std::string>> cases{
      {"because: The sky is blue over deserts too.\n", "", "q.md:15: error: this choice has no 'because:'"},
      {"right: Rayleigh scattering.\n", "wrong: Rayleigh scattering.\n",
       "q.md:14: error: a ```question block needs exactly one 'right:'"},
      {"  reflects it.\n", "reflects it.\n", "q.md:16: error: expected 'right: ...'"},
      {"```question\n", "```question\nbecause: early\n", "q.md:15: error: 'because:' explains"},
      {"stage: exercise\n", "stage: exercise\ntopic: southwell\n", "not both"},
      {"stage: exercise\n", "stage: text\n",
       "q.md:14: error: a ```question block belongs to an exercise step"},
  };
  for (const auto& [from, to, expected] : cases) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    try {
      parseLesson(text, "q", "q.md");
      ADD_FAILURE() << "accepted: " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace rt::lesson
