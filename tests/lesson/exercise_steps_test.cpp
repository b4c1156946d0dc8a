// Exercise steps: every shipped lesson ends with at least two, each names a topic whose row lists the lesson,
// runs without a scene into a question with its key, and an exercise step without a topic is an error at its
// line.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "homework/topic_table.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_runner.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

TEST(ExerciseSteps, EveryLessonEndsWithTwoExercisesOfItsTopics) {
  const auto folders = test::repoFolders();
  StepRunner runner(folders.scenes);
  for (const Lesson& lesson : loadCatalogue(folders)) {
    SCOPED_TRACE(lesson.id);
    ASSERT_GE(lesson.steps.size(), 2u);
    for (std::size_t k = lesson.steps.size() - 2; k < lesson.steps.size(); ++k) {
      const Step& step = lesson.steps[k];
      ASSERT_EQ(step.stage, Stage::Exercise) << step.title;
      const homework::Topic* topic = homework::findTopic(step.parameters.topic);
      ASSERT_NE(topic, nullptr);
      EXPECT_NE(std::string(topic->lessons).find(lesson.id), std::string::npos)
          << "the topic table's row of " << topic->id << " should list " << lesson.id;
      const StepResult result = runner.run(lesson, step);
      ASSERT_TRUE(result.exercise.has_value());
      EXPECT_FALSE(result.exercise->questions.empty());
      EXPECT_EQ(result.exercise->seed, step.parameters.seed.value_or(1));
      const auto& q = result.exercise->questions.front();
      EXPECT_EQ(result.value("answer." + q.id), q.answer);
      EXPECT_NO_THROW(resolvedText(lesson, step, result));
    }
  }
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

}  // namespace
}  // namespace rt::lesson
