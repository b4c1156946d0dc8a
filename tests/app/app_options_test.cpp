// The command line: lesson, step, screenshot and size are read, and wrong values are named in clear errors.
#include <gtest/gtest.h>

#include "app/app_options.h"
#include "support/test_paths.h"

using rt::app::AppOptions;
using rt::app::parseAppOptions;

TEST(AppOptions, ReadsLessonStepScreenshotAndSize) {
  QString error;
  const AppOptions o = parseAppOptions({"radiosity-textbook", "--lesson", "cornell-box", "--step", "3",
                                        "--screenshot", "out.png", "--size", "800x600"},
                                       &error);
  EXPECT_TRUE(error.isEmpty()) << error.toStdString();
  EXPECT_EQ(o.lesson, "cornell-box");
  EXPECT_EQ(o.step, 3);
  EXPECT_EQ(o.screenshot, "out.png");
  EXPECT_EQ(o.size, QSize(800, 600));
}

TEST(AppOptions, DefaultsOpenTheRememberedPosition) {
  QString error;
  const AppOptions o = parseAppOptions({"radiosity-textbook"}, &error);
  EXPECT_TRUE(error.isEmpty());
  EXPECT_TRUE(o.lesson.isEmpty());
  EXPECT_EQ(o.step, 0);
  EXPECT_EQ(o.size, QSize(1600, 1000));
}

TEST(AppOptions, RejectsBadValuesWithTheirName) {
  QString error;
  parseAppOptions({"radiosity-textbook", "--step", "zero"}, &error);
  EXPECT_TRUE(error.contains("--step")) << error.toStdString();
  error.clear();
  parseAppOptions({"radiosity-textbook", "--size", "big"}, &error);
  EXPECT_TRUE(error.contains("--size")) << error.toStdString();
  error.clear();
  parseAppOptions({"radiosity-textbook", "--screenshot", "out.jpg"}, &error);
  EXPECT_TRUE(error.contains("PNG")) << error.toStdString();
  error.clear();
  parseAppOptions({"radiosity-textbook", "--scene", "a.json", "--lesson", "x"}, &error);
  EXPECT_FALSE(error.isEmpty());
  error.clear();
  parseAppOptions({"radiosity-textbook", "--no-such-option"}, &error);
  EXPECT_TRUE(error.contains("no-such-option")) << error.toStdString();
}

TEST(AppOptions, CompareChoicesImplyCompareMode) {
  QString error;
  const AppOptions o = parseAppOptions(
      {"radiosity-textbook", "--compare-solver", "jacobi", "--compare-mesh", "adaptive"}, &error);
  EXPECT_TRUE(error.isEmpty()) << error.toStdString();
  EXPECT_TRUE(o.compare);
  EXPECT_EQ(o.compareSolver, "jacobi");
  EXPECT_EQ(o.compareMesh, "adaptive");
  EXPECT_TRUE(o.compareMethod.isEmpty());
  parseAppOptions({"radiosity-textbook", "--compare-mesh", "wavy"}, &error);
  EXPECT_TRUE(error.contains("--compare-mesh") && error.contains("hierarchical")) << error.toStdString();
}

// --help and --version answer in a terminal with no display at all: no DISPLAY, no Wayland, no QPA platform
// chosen (a window system is needed only to open the window).
TEST(AppOptions, HelpAndVersionNeedNoDisplay) {
  const std::string app = rt::test::binaryPath("bin/radiosity-textbook");
  const std::string bare = "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM " + app;
  std::string output;
  EXPECT_EQ(rt::test::runCommand(bare + " --help", &output), 0) << output;
  EXPECT_NE(output.find("Usage:"), std::string::npos) << output;
  EXPECT_NE(output.find("--lesson <id>"), std::string::npos) << output;
  EXPECT_NE(output.find("--screenshot <file>"), std::string::npos) << output;
  EXPECT_EQ(rt::test::runCommand(bare + " --version", &output), 0) << output;
  EXPECT_NE(output.find("radiosity-textbook 0.1.0"), std::string::npos) << output;
  EXPECT_EQ(rt::test::runCommand(bare + " -h --no-such-option", &output), 2) << output;
  EXPECT_NE(output.find("no-such-option"), std::string::npos) << output;
}
