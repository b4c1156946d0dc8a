// The table of step keys is the one source of the parser's keys, the panel's controls and the docs: every
// key a lesson names as a control is in the table as a control, the docs show the table as it is, and a
// value goes through the table with its range.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "lesson/lesson_loader.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_keys.h"
#include "lesson_test_support.h"
#include "support/test_paths.h"

using namespace rt::lesson;

TEST(StepKeys, EveryControlInTheLessonsIsAControlOfTheTable) {
  const auto folders = test::repoFolders();
  int controls = 0;
  for (const auto& file : lessonFiles(folders.lessons)) {
    const Lesson lesson = loadLesson(file, folders.scenes);
    for (const auto& step : lesson.steps)
      for (const auto& c : step.controls) {
        const StepKey* key = findStepKey(c);
        ASSERT_NE(key, nullptr) << lesson.id << ": " << c;
        EXPECT_TRUE(key->control) << lesson.id << ": " << c;
        EXPECT_TRUE(key->acceptedBy(step.stage))
            << lesson.id << ": " << c << " on stage " << toString(step.stage);
        ++controls;
      }
  }
  EXPECT_GT(controls, 30);
}

TEST(StepKeys, TheDocsShowTheTableAsItIs) {
  std::ifstream in(rt::test::sourcePath("docs/lesson-format.md"));
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(stepKeyTableMarkdown()), std::string::npos)
      << "docs/lesson-format.md does not hold the current table; `radiosity lesson keys` prints it:\n"
      << stepKeyTableMarkdown();
}

TEST(StepKeys, TheDocsShowTheTableOfStagesAsItIs) {
  std::ifstream in(rt::test::sourcePath("docs/lesson-format.md"));
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(stageTableMarkdown()), std::string::npos)
      << "docs/lesson-format.md does not hold the current table; `radiosity lesson stages` prints it:\n"
      << stageTableMarkdown();
  // Every stage is in the table, and a view a stage does not offer is refused by the parser.
  for (const std::string& name : stageNames()) EXPECT_TRUE(stageFromString(name)) << name;
  EXPECT_TRUE(stageOffersView(Stage::Hemicube, View::Hemicube));
  EXPECT_FALSE(stageOffersView(Stage::Solve, View::Hemicube));
}

TEST(StepKeys, ValuesGoThroughTheTableWithTheirRanges) {
  StepParameters p;
  applyStepValue(p, *findStepKey("resolution"), "resolution", "64", {"x.md", 3});
  EXPECT_EQ(p.resolution.value_or(0), 64);
  applyStepValue(p, *findStepKey("reflectance"), "reflectance.floor", "0.1 0.2 0.3", {"x.md", 4});
  EXPECT_DOUBLE_EQ(p.reflectance.at("floor")[2], 0.3);
  EXPECT_EQ(stepValueText(p, *findStepKey("reflectance"), "reflectance.floor").value_or(""), "0.1 0.2 0.3");
  try {
    applyStepValue(p, *findStepKey("tolerance"), "tolerance", "5", {"x.md", 7});
    FAIL() << "accepted a tolerance of 5";
  } catch (const rt::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.md:7"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[1e-15, 0.5]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(applyStepValue(p, *findStepKey("solver"), "solver", "guess", {"x.md", 8}), rt::InputError);
}

// A bound past an int's range (the work budget's is 1e15) belongs to a double key and is read as a double.
TEST(StepKeys, ABoundPastAnIntsRangeIsReadOnlyByDoubleKeys) {
  StepParameters p;
  applyStepValue(p, *findStepKey("ff-budget"), "ff-budget", "1e15", {"x.md", 3});
  EXPECT_DOUBLE_EQ(p.formFactorBudget.value_or(0), 1e15);
  EXPECT_THROW(applyStepValue(p, *findStepKey("ff-budget"), "ff-budget", "2e15", {"x.md", 4}),
               rt::InputError);
}

TEST(StepKeys, ALessonCanOnlyNameControlsThatExist) {
  const std::string text =
      "---\ntitle: T\norder: 1\n---\n\n## S\n\n```step\nscene: cornell-box.json\nstage: scene\ncontrols: "
      "subdivide, wobble\n```\n\nText.\n";
  try {
    parseLesson(text, "t", "t.md");
    FAIL() << "a control that does not exist was accepted";
  } catch (const rt::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.md:11"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'wobble' cannot be a control"), std::string::npos) << e.what();
  }
}
