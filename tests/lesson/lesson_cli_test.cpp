// `radiosity lesson list` and `radiosity lesson check` as a user runs them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/test_paths.h"

namespace {

std::string cli() {
  return rt::test::cliPath() + " lesson ";
}

TEST(LessonCli, ListsTheLessonsInBookOrder) {
  std::string out;
  ASSERT_EQ(rt::test::runCommand(cli() + "list --root " + rt::test::sourcePath(""), &out), 0) << out;
  const auto first = out.find("local-vs-global");
  const auto cornell = out.find("cornell-box");
  const auto last = out.find("numerical-stability");
  ASSERT_NE(first, std::string::npos) << out;
  ASSERT_NE(cornell, std::string::npos) << out;
  ASSERT_NE(last, std::string::npos) << out;
  EXPECT_LT(first, cornell);
  EXPECT_LT(cornell, last);
}

TEST(LessonCli, CheckAcceptsTheShippedLessons) {
  std::string out;
  EXPECT_EQ(rt::test::runCommand(cli() + "check --all --root " + rt::test::sourcePath(""), &out), 0) << out;
  EXPECT_NE(out.find("ok      cornell-box"), std::string::npos) << out;
}

TEST(LessonCli, CheckReportsEveryBrokenLessonWithFileAndLine) {
  const std::string root = rt::test::scratchDir("lesson-cli-check");
  std::filesystem::create_directories(root + "/lessons");
  std::filesystem::copy(rt::test::sourcePath("scenes"), root + "/scenes");
  std::ofstream(root + "/lessons/broken.md")
      << "---\ntitle: Broken\norder: 1\n---\n## A\n```step\nscene: parallel-squares.json\nstage: solve\n"
         "solver: guess\n```\n";
  std::ofstream(root + "/lessons/surface.md")
      << "---\ntitle: Surface\norder: 2\n---\n## A\n```step\nscene: parallel-squares.json\nstage: scene\n"
         "highlight: ceiling\n```\n";
  std::string out;
  EXPECT_NE(rt::test::runCommand(cli() + "check --all --root " + root, &out), 0) << out;
  EXPECT_NE(out.find("broken.md:9: error: unknown solver 'guess'"), std::string::npos) << out;
  EXPECT_NE(out.find("surface.md:9: error: scene 'parallel-squares.json' has no surface 'ceiling'"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("2 lesson(s) have errors"), std::string::npos) << out;
}

TEST(LessonCli, UnknownLessonNamesTheKnownOnes) {
  std::string out;
  EXPECT_NE(rt::test::runCommand(cli() + "check nonsense --root " + rt::test::sourcePath(""), &out), 0);
  EXPECT_NE(out.find("no lesson 'nonsense'"), std::string::npos) << out;
  EXPECT_NE(out.find("cornell-box"), std::string::npos) << out;
}

}  // namespace
