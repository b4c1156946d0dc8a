// The lessons shipped in lessons/: every one loads, names existing scenes and surfaces, and the book order is
// complete. A lesson dropped into a folder appears in the catalogue without any compilation.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "core/input_error.h"
#include "lesson/lesson_loader.h"
#include "support/test_paths.h"

namespace rt::lesson {
namespace {

LessonFolders repoFolders() {
  return foldersUnder(rt::test::sourcePath(""));
}

TEST(LessonCatalogue, EveryShippedLessonLoadsAndMatchesItsScenes) {
  const auto folders = repoFolders();
  for (const auto& file : lessonFiles(folders.lessons)) {
    SCOPED_TRACE(file);
    try {
      const Lesson lesson = loadLesson(file, folders.scenes);
      EXPECT_GE(lesson.steps.size(), 3u) << "a lesson has several steps";
      checkAgainstScenes(lesson, folders.scenes);
    } catch (const InputError& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

TEST(LessonCatalogue, IsSortedByOrderAndCoversTheCourse) {
  const auto lessons = loadCatalogue(repoFolders());
  ASSERT_GE(lessons.size(), 17u);
  std::set<int> orders;
  for (std::size_t i = 0; i < lessons.size(); ++i) {
    if (i > 0) {
      EXPECT_LE(lessons[i - 1].order, lessons[i].order);
    }
    EXPECT_TRUE(orders.insert(lessons[i].order).second) << "two lessons share order " << lessons[i].order;
  }
  for (int order = 1; order <= 17; ++order) EXPECT_TRUE(orders.count(order)) << "no lesson " << order;
  const bool hasCornell =
      std::any_of(lessons.begin(), lessons.end(), [](const Lesson& l) { return l.id == "cornell-box"; });
  EXPECT_TRUE(hasCornell) << "the README renders lesson 'cornell-box'";
}

TEST(LessonCatalogue, ANewFileIsANewLesson) {
  const std::string root = rt::test::scratchDir("lesson-catalogue");
  std::filesystem::create_directories(root + "/lessons");
  std::filesystem::create_directories(root + "/scenes");
  std::ofstream(root + "/scenes/a.json") << "{}";
  std::ofstream(root + "/lessons/second.md")
      << "---\ntitle: B\norder: 2\n---\n## S\n```step\nstage: text\n```\n";
  std::ofstream(root + "/lessons/first.md")
      << "---\ntitle: A\norder: 1\n---\n## S\n```step\nscene: a.json\nstage: scene\n```\n";
  auto lessons = loadCatalogue(foldersUnder(root));
  ASSERT_EQ(lessons.size(), 2u);
  EXPECT_EQ(lessons[0].id, "first");
  EXPECT_EQ(lessons[1].id, "second");
  EXPECT_EQ(lessonPath(foldersUnder(root), "second"), root + "/lessons/second.md");
  EXPECT_THROW(lessonPath(foldersUnder(root), "third"), InputError);
}

TEST(LessonCatalogue, AMissingSceneIsAnErrorAtItsLine) {
  const std::string root = rt::test::scratchDir("lesson-missing-scene");
  std::filesystem::create_directories(root + "/lessons");
  std::filesystem::create_directories(root + "/scenes");
  std::ofstream(root + "/lessons/x.md")
      << "---\ntitle: A\norder: 1\n---\n## S\n```step\nstage: scene\nscene: nowhere.json\n```\n";
  try {
    loadLesson(root + "/lessons/x.md", root + "/scenes");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 8);
    EXPECT_NE(std::string(e.what()).find("nowhere.json"), std::string::npos);
  }
}

TEST(LessonCatalogue, UnknownSurfacesAreErrorsAtTheirLine) {
  const auto folders = repoFolders();
  const std::string root = rt::test::scratchDir("lesson-unknown-surface");
  const std::string file = root + "/x.md";
  std::ofstream(file)
      << "---\ntitle: A\norder: 1\n---\n## S\n```step\nscene: parallel-squares.json\nstage: scene\n"
         "reflectance.nothing: 0.5\n```\n";
  const Lesson lesson = loadLesson(file, folders.scenes);
  try {
    checkAgainstScenes(lesson, folders.scenes);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 9);
    EXPECT_NE(std::string(e.what()).find("receiver"), std::string::npos) << "lists the surfaces it has";
  }
}

}  // namespace
}  // namespace rt::lesson
