// The exact-visibility view: drawn from plain regions; through the CLI when the exact reference is built in.
#include <gtest/gtest.h>

#include "lesson/lesson_parser.h"
#include "lesson/step_runner.h"
#include "support/test_paths.h"
#include "viz/exact_visibility.h"
#include "viz/lesson_figures.h"
#include "viz/visibility_view.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

VisibilityRegions squareWithShadow() {
  VisibilityRegions r;
  r.source = 0;
  r.receiver = 1;
  r.receiverOutline = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  r.shadows = {{{0.25, 0.25, 1}, {0.75, 0.25, 1}, {0.75, 0.75, 1}, {0.25, 0.75, 1}}};
  r.shadowOwners = {2};
  r.visible = {{r.receiverOutline, {{{0.25, 0.25, 1}, {0.25, 0.75, 1}, {0.75, 0.75, 1}, {0.75, 0.25, 1}}}}};
  r.formFactor = 0.1;
  r.unoccludedFormFactor = 0.2;
  return r;
}

TEST(VisibilityView, DrawsReceiverShadowsAndBoundaries) {
  const Drawing d = visibilityDrawing(squareWithShadow(), {});
  // Receiver, shadow, and the two legend swatches are filled; the visible region's outer boundary, its hole
  // and the receiver's outline are drawn.
  EXPECT_EQ(d.count(Drawing::Kind::Polygon), 4u);
  EXPECT_EQ(d.count(Drawing::Kind::Polyline), 3u);
  bool numbers = false;
  for (const auto& s : d.shapes) numbers |= s.text.find("0.100000") != std::string::npos;
  EXPECT_TRUE(numbers);
}

TEST(VisibilityView, VectorAndRasterFiles) {
  const std::string dir = test::scratchDir("visibility_view");
  VisibilityViewOptions o;
  o.size = {500, 400, 96};
  writeVisibilityFigure(squareWithShadow(), o, dir + "/v.svg");
  writeVisibilityFigure(squareWithShadow(), o, dir + "/v.png");
  const std::string svg = vizt::readFile(dir + "/v.svg");
  EXPECT_TRUE(svg.find("<path") != std::string::npos || svg.find("<polygon") != std::string::npos);
  EXPECT_GT(vizt::pngStats(dir + "/v.png").stddev, 20.0);
}

TEST(VisibilityView, ThroughTheCliWhenTheExactReferenceIsBuilt) {
  const std::string out = test::scratchDir("visibility_cli") + "/v.png";
  std::string log;
  const int code =
      test::runCommand(test::cliPath() + " figure " + test::sourcePath("scenes/cornell-box.json") +
                           " --view visibility --width 480 --height 360 --output " + out,
                       &log);
  if (code != 0 && log.find("needs the exact reference") != std::string::npos)
    GTEST_SKIP() << "built without the exact reference";
  ASSERT_EQ(code, 0) << log;
  EXPECT_GT(vizt::pngStats(out).stddev, 15.0);
}

// A lesson's `visibility` view is the command line's: the exact visible part of the target, the same figure.
TEST(VisibilityView, ALessonStepDrawsWhatTheCommandLineDraws) {
  if (!exactVisibilityAvailable()) GTEST_SKIP() << "built without the exact reference";
  const std::string dir = test::scratchDir("visibility_lesson");
  const std::string text =
      "---\ntitle: V\norder: 1\n---\n\n## Seen from the source\n\n```step\nscene: occluded-plates.json\n"
      "stage: formfactors\nfrom: 0\nhighlight: 1\nviews: visibility\nfigure: seen\n```\n\nText.\n";
  const lesson::Lesson l = lesson::parseLesson(text, "v", "v.md");
  lesson::StepRunner runner(test::sourcePath("scenes"));
  const lesson::StepResult r = runner.run(l, l.steps[0]);
  const auto figures = renderStepFigures(l, l.steps[0], r, dir, {480, 360});
  ASSERT_EQ(figures.size(), 1u);
  std::string log;
  ASSERT_EQ(test::runCommand(
                test::cliPath() + " figure " + test::sourcePath("scenes/occluded-plates.json") +
                    " --no-subdivide --view visibility --element 0 --target 1 --width 480 --height 360 "
                    "--output " +
                    dir + "/cli.png",
                &log),
            0)
      << log;
  EXPECT_GT(vizt::pngStats(dir + "/seen.png").stddev, 15.0);
  EXPECT_LT(vizt::pngDifference(dir + "/seen.png", dir + "/cli.png"), 0.5);
}

}  // namespace
}  // namespace rt::viz
