// References between lessons: the text names a lesson by id and the number comes from the lesson's order, so
// inserting a chapter renumbers every reference. The shipped lessons type no lesson number themselves.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "core/input_error.h"
#include "lesson/book_html.h"
#include "lesson/lesson_loader.h"
#include "lesson/lesson_references.h"
#include "lesson/maths.h"
#include "lesson/text_apparatus.h"
#include "lesson_test_support.h"
#include "support/test_paths.h"

namespace rt::lesson {
namespace {

TEST(LessonReferences, BecomeLinksNumberedByTheOtherLessonsOrder) {
  const LessonNumbers numbers{{"form-factor", 6}, {"measuring-light", 2}};
  EXPECT_EQ(prepareLessonReferences("As @lesson:form-factor shows. @Lesson:measuring-light's law.", 10,
                                    "x.md", numbers),
            "As [lesson 6](form-factor.html#top) shows. [Lesson 2](measuring-light.html#top)'s law.");
  // The book's lessons are chapters.
  EXPECT_EQ(prepareLessonReferences("As @lesson:form-factor shows. @Lesson:measuring-light's law.", 10,
                                    "x.md", numbers, "chapter"),
            "As [chapter 6](form-factor.html#top) shows. [Chapter 2](measuring-light.html#top)'s law.");
  // Code and maths are left as written.
  EXPECT_EQ(prepareLessonReferences("`@lesson:form-factor` and $@lesson:x$", 1, "x.md", numbers),
            "`@lesson:form-factor` and $@lesson:x$");
}

TEST(LessonReferences, AnUnknownLessonIsAnErrorAtItsLineListingTheKnownOnes) {
  try {
    prepareLessonReferences("One.\nSee @lesson:hemicub.\n", 20, "lessons/a.md", {{"hemicube", 8}});
    FAIL() << "an unknown lesson was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("lessons/a.md:21"), std::string::npos) << what;
    EXPECT_NE(what.find("'@lesson:hemicub'"), std::string::npos) << what;
    EXPECT_NE(what.find("known: hemicube"), std::string::npos) << what;
  }
}

TEST(LessonReferences, NumbersComeFromTheFilesBesideTheLessonAndFollowANewChapter) {
  const std::string root = rt::test::scratchDir("lesson-references");
  std::filesystem::create_directories(root + "/lessons");
  auto write = [&](const std::string& id, int order, const std::string& text) {
    std::ofstream(root + "/lessons/" + id + ".md")
        << "---\ntitle: " << id << "\norder: " << order << "\n---\n\n## S\n\n```step\nstage: text\n```\n\n"
        << text << "\n";
  };
  write("a", 1, "See @lesson:b.");
  write("b", 2, "Text.");
  EXPECT_EQ(lessonNumbers(root + "/lessons"), (LessonNumbers{{"a", 1}, {"b", 2}}));
  write("b", 3, "Text.");  // a chapter went in before it
  write("new", 2, "Text.");
  const LessonNumbers numbers = lessonNumbers(root + "/lessons");
  EXPECT_EQ(numbers.at("b"), 3);
  EXPECT_EQ(prepareLessonReferences("See @lesson:b.", 1, "a.md", numbers), "See [lesson 3](b.html#top).");
  EXPECT_TRUE(lessonNumbers(root + "/nowhere").empty());
}

TEST(LessonReferences, InThePrintedBookTheLinkPointsToTheChapter) {
  RenderedLesson a;
  a.id = "a";
  a.order = 1;
  a.title = "A";
  a.steps.push_back({"S", "See [lesson 2](b.html#top).\n", {}});
  RenderedLesson b = a;
  b.id = "b";
  b.order = 2;
  b.title = "B";
  EXPECT_NE(printBookHtml({a, b}).find("href=\"#c2-top\""), std::string::npos);
}

TEST(ShippedLessons, NameOtherLessonsByIdNeverByNumber) {
  const auto folders = test::repoFolders();
  const std::regex typed("\\b[Ll]essons? [0-9]+|\\b[Cc]hapters? [0-9]+");
  for (const std::string& file : lessonFiles(folders.lessons)) {
    const Lesson l = loadLesson(file, folders.scenes);
    auto check = [&](const std::string& text) {
      for (const auto& [begin, end] : plainTextPieces(text)) {
        const std::string piece = text.substr(begin, end - begin);
        std::smatch m;
        EXPECT_FALSE(std::regex_search(piece, m, typed)) << l.id << " types '" << m.str() << "'";
      }
    };
    check(l.intro);
    for (const Step& s : l.steps) check(s.text);
  }
}

}  // namespace
}  // namespace rt::lesson
