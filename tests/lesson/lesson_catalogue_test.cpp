// The lessons shipped in lessons/: every one loads, names existing scenes and surfaces, and the book order is
// unique and sorted. A lesson dropped into a folder appears in the catalogue without any compilation.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "core/input_error.h"
#include "lesson/book_html.h"
#include "lesson/lesson_loader.h"
#include "lesson/markdown_html.h"
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
  // Orders are unique and sorted; gaps are allowed (chapters written elsewhere take their places later).
  EXPECT_EQ(*orders.begin(), 1) << "the book starts at chapter 1";
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

// A note for readers of the course slides is a blockquote starting with its bold label, and a blockquote is
// drawn as a box in the book (the app's text view has the same rule).
TEST(LessonCatalogue, SlideNotesAreBoxedBlockquotes) {
  const std::string html = markdownToHtml("> **Reading the slides.** The unit of radiosity is W/m^2.\n");
  EXPECT_NE(html.find("<blockquote>"), std::string::npos) << html;
  const std::string css = bookStyleSheet();
  const auto rule = css.find("blockquote {");
  ASSERT_NE(rule, std::string::npos);
  EXPECT_NE(css.find("border:", rule), std::string::npos) << "a box, not a bar";
  int notes = 0;
  for (const auto& file : lessonFiles(repoFolders().lessons)) {
    std::ifstream in(file);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      if (line.find("Reading the slides") == std::string::npos) continue;
      ++notes;
      EXPECT_EQ(line.rfind("> **Reading the slides.**", 0), 0u) << file << ":" << number;
    }
  }
  EXPECT_GT(notes, 0);
}

}  // namespace
}  // namespace rt::lesson
