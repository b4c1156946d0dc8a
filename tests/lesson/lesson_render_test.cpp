// The book is built as part of the tests: every shipped lesson is rendered with small parameters through the
// CLI, and every figure its steps name must exist and show something (not one flat colour).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "lesson/lesson_loader.h"
#include "lesson_test_support.h"
#include "support/test_paths.h"

namespace rt::lesson {
namespace {

TEST(LessonRender, EveryLessonRendersWithAllItsFigures) {
  const std::string out = rt::test::scratchDir("lesson-book");
  const bool haveDisplay = std::getenv("DISPLAY") != nullptr;
  const bool haveXvfb = rt::test::runCommand("command -v xvfb-run") == 0;
  if (!haveDisplay && !haveXvfb) GTEST_SKIP() << "no X display and no xvfb-run: figures cannot be drawn";
  std::string command = rt::test::cliPath() + " lesson render --all --quick --root " +
                        rt::test::sourcePath("") + " --output " + out;
  // -noreset: Xvfb otherwise resets whenever its last client leaves, and the next figure's connection can
  // fail.
  if (!haveDisplay) command = "xvfb-run -a -s '-screen 0 1280x1024x24 -noreset' " + command;
  std::string log;
  // Several xvfb-run -a started at once can race for a display number: retry when the X connection failed.
  int status = rt::test::runCommand(command, &log);
  for (int attempt = 0;
       attempt < 2 && status != 0 && log.find("bad X server connection") != std::string::npos; ++attempt)
    status = rt::test::runCommand(command, &log);
  ASSERT_EQ(status, 0) << log;
  EXPECT_TRUE(std::filesystem::exists(out + "/index.md"));
  const bool drawsFigures = log.find("no viz library") == std::string::npos;

  // Steps needing a method this build lacks (the exact reference without CGAL) are listed, not drawn.
  std::set<std::string> skipped;
  {
    std::ifstream list(out + "/skipped.txt");
    for (std::string line; std::getline(list, line);)
      if (!line.empty()) skipped.insert(line);
  }
  EXPECT_LE(skipped.size(), 6u) << "only steps of optional methods may be skipped";
  const auto lessons = loadCatalogue(test::repoFolders());
  std::vector<std::string> figures;
  for (const auto& lesson : lessons) {
    const std::string page = out + "/" + lesson.id + ".md";
    ASSERT_TRUE(std::filesystem::exists(page)) << page;
    std::ifstream in(page);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str().find("{{"), std::string::npos) << page << ": unresolved placeholder";
    if (!drawsFigures) continue;
    for (const auto& step : lesson.steps)
      for (const auto& file : step.figureFiles()) {
        if (skipped.count(lesson.id + "/" + file)) continue;
        const std::string path = out + "/" + lesson.id + "/" + file;
        if (!std::filesystem::exists(path)) {
          ADD_FAILURE() << "missing figure " << path;
          continue;
        }
        EXPECT_NE(text.str().find(lesson.id + "/" + file), std::string::npos)
            << page << " does not show " << file;
        figures.push_back(path);
      }
  }
  if (!drawsFigures)
    GTEST_SKIP() << "the CLI was built without the viz library: pages checked, figures not drawn";
  ASSERT_FALSE(figures.empty());

  // Non-blank: more than a handful of colours, and no single colour covering almost everything.
  if (rt::test::runCommand("python3 -c 'import zlib'") != 0)
    GTEST_SKIP() << "python3 is needed to read the PNGs";
  std::string stats;
  std::string statsCommand = "python3 " + rt::test::sourcePath("tests/lesson/png_stats.py");
  for (const auto& f : figures) statsCommand += " " + f;
  ASSERT_EQ(rt::test::runCommand(statsCommand, &stats), 0) << stats;
  std::istringstream lines(stats);
  std::string path;
  int width = 0, height = 0, colours = 0;
  double dominant = 0;
  int checked = 0;
  while (lines >> path >> width >> height >> colours >> dominant) {
    ++checked;
    EXPECT_GT(colours, 4) << path << " is blank";
    EXPECT_LT(dominant, 0.99) << path << " is almost one colour";
  }
  EXPECT_EQ(checked, static_cast<int>(figures.size())) << stats;
}

}  // namespace
}  // namespace rt::lesson
