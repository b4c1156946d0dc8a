// A lesson step's view by name (`camera: NAME`) and its camera path (`camera-path`, `path-frames`): parsed
// with their lines, checked against the scene's cameras with the lesson's file and line, applied by the step
// runner, and exported headless by `radiosity lesson render` as numbered frames.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "core/io/scene_loader.h"
#include "lesson/lesson_loader.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_runner.h"
#include "lesson_test_support.h"
#include "support/test_paths.h"

namespace rt::lesson {
namespace {

std::string lessonWith(const std::string& keys, const std::string& views = "scene") {
  return "---\ntitle: Views\norder: 1\n---\n## A\n```step\nscene: cornell-box-closed.json\nstage: solve\n"
         "max-edge: 200\n" +
         keys + "views: " + views + "\nfigure: tour\n```\nText.\n";
}

TEST(CameraSteps, TheKeysAreReadWithTheirLines) {
  const Lesson l = parseLesson(
      lessonWith("camera: above\ncamera-path: left, above, right\npath-frames: 12\n"), "views", "views.md");
  const Step& s = l.steps.front();
  EXPECT_EQ(s.camera.name, "above");
  EXPECT_EQ(s.camera.path, (std::vector<std::string>{"left", "above", "right"}));
  EXPECT_EQ(s.camera.pathFrames, 12);
  EXPECT_NE(
      test::inputErrorOf([] { parseLesson(lessonWith("camera-path: left\n"), "v", "v.md"); }).find("v.md:10"),
      std::string::npos);
  const std::string noPath =
      test::inputErrorOf([] { parseLesson(lessonWith("", "walkthrough"), "v", "v.md"); });
  EXPECT_NE(noPath.find("the walkthrough view needs a 'camera-path'"), std::string::npos) << noPath;
}

TEST(CameraSteps, AnUnknownCameraNamesTheLessonLineAndTheScenesCameras) {
  const Lesson l = parseLesson(lessonWith("camera-path: left, nowhere\n"), "views", "views.md");
  const std::string error = test::inputErrorOf([&] { checkAgainstScenes(l, test::repoFolders().scenes); });
  EXPECT_NE(error.find("views.md:10"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown camera 'nowhere' (the scene's cameras: "), std::string::npos) << error;
  EXPECT_NE(error.find("above"), std::string::npos) << error;
  const Lesson named = parseLesson(lessonWith("camera: nowhere\n"), "views", "views.md");
  StepRunner runner(test::repoFolders().scenes, RunOptions{.quick = true});
  const std::string atRun = test::inputErrorOf([&] { runner.run(named, named.steps.front()); });
  EXPECT_NE(atRun.find("views.md:10"), std::string::npos) << atRun;
}

TEST(CameraSteps, TheRunnerLooksThroughTheNamedCameraAndFliesThePath) {
  test::ensureAnalyticMethod();
  const Scene scene = loadScene(test::repoFolders().scenes + "/cornell-box-closed.json");
  const Lesson l = parseLesson(
      lessonWith("camera: above\ncamera.fov: 30\ncamera-path: left, above, right\npath-frames: 5\n"), "views",
      "views.md");
  StepRunner runner(test::repoFolders().scenes, RunOptions{.quick = true});
  const StepResult r = runner.run(l, l.steps.front());
  EXPECT_TRUE(r.camera.position.isApprox(scene.findCamera("above")->position));
  EXPECT_EQ(r.camera.fovYDegrees, 30) << "camera.* adjusts the named camera";
  ASSERT_EQ(r.cameraPath.size(), 5u);
  EXPECT_TRUE(r.cameraPath.front().position.isApprox(scene.findCamera("left")->position));
  EXPECT_TRUE(r.cameraPath[2].target.isApprox(scene.findCamera("above")->target, 1e-6));
  EXPECT_TRUE(r.cameraPath.back().position.isApprox(scene.findCamera("right")->position));
}

TEST(CameraSteps, LessonRenderWritesTheWalkthroughAsNumberedFrames) {
  const std::string root = rt::test::scratchDir("camera-steps-render");
  std::filesystem::create_directories(root + "/lessons");
  std::filesystem::copy(rt::test::sourcePath("scenes"), root + "/scenes");
  std::ofstream(root + "/lessons/tour.md")
      << lessonWith("camera-path: left, above, right\npath-frames: 4\n", "walkthrough");
  std::string log;
  ASSERT_EQ(rt::test::runCommand(rt::test::cliPath() + " lesson render tour --quick --root " + root +
                                     " --output " + root + "/out",
                                 &log),
            0)
      << log;
  if (log.find("this build has no viz library") != std::string::npos)
    GTEST_SKIP() << "the CLI was built without the viz library: the page is written, no frames drawn";
  EXPECT_TRUE(std::filesystem::exists(root + "/out/tour/tour.png")) << log;
  for (int f = 1; f <= 4; ++f)
    EXPECT_TRUE(std::filesystem::exists(root + "/out/tour/tour-000" + std::to_string(f) + ".png")) << f;
  EXPECT_FALSE(std::filesystem::exists(root + "/out/tour/tour-0005.png"));
}

}  // namespace
}  // namespace rt::lesson
