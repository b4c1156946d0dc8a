// The scaling stage's `scenes`: one scene written at several sizes, solved by hierarchical-clustering, its
// links against n. Checked on "Hierarchical radiosity", step "Links against n on the museum and the factory":
// the six files fall into two series by the scene's name, the links grow far slower than the n^2 pairs, the
// links per element settle, one link stands for more pairs as n grows, and a looser tolerance keeps fewer;
// and a file that does not exist is an error at the `scenes` line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "lesson/step_runner.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

constexpr const char* kFigure = "links-large-scenes";

TEST(SceneLinks, TheMuseumAndTheFactoryKeepLinksFarSlowerThanTheirPairsAtAnyTolerance) {
  const test::RanStep s = test::runStepWithFigure("hierarchical", kFigure);
  ASSERT_TRUE(s.result.scaling);
  const auto& series = s.result.scaling->sceneLinks;
  ASSERT_EQ(series.size(), 2u) << "the six files are two scenes";
  EXPECT_EQ(series[0].key, "museum");
  EXPECT_EQ(series[1].key, "factory-hall");
  for (const SceneLinksSeries& scene : series) {
    ASSERT_EQ(scene.points.size(), 3u) << scene.name;
    for (std::size_t k = 0; k < scene.points.size(); ++k) {
      const SceneLinksPoint& p = scene.points[k];
      const double n = static_cast<double>(p.elements);
      // "three sizes each ... about N polygons, one element each": 1k, 4k and 16k within a tenth.
      EXPECT_NEAR(n / (1000.0 * static_cast<double>(1 << (2 * k))), 1.0, 0.1) << p.file;
      EXPECT_LT(static_cast<double>(p.links), n * n) << p.file;
    }
    const std::string& key = scene.key;
    // "The fitted slopes ... against the 2 of the n^2 pairs": about 1, far below 2.
    EXPECT_GT(s["links-slope." + key], 0.8) << key;
    EXPECT_LT(s["links-slope." + key], 1.4) << key;
    // "... and settle": the two larger sizes within a quarter of each other.
    EXPECT_NEAR(s["links-per-element." + key + "[2]"] / s["links-per-element." + key + "[1]"], 1.0, 0.25)
        << key;
    // "one link stands for ... element pairs ... and the ratio grows with n".
    EXPECT_GT(s["pairs-per-link." + key + "[1]"], s["pairs-per-link." + key + "[0]"]) << key;
    EXPECT_GT(s["pairs-per-link." + key + "[2]"], s["pairs-per-link." + key + "[1]"]) << key;
    EXPECT_GT(s["pairs-per-link." + key + "[2]"], 50) << key;
  }
  // "on the coarsest museum ... the links per element still rise".
  EXPECT_GT(s["links-per-element.museum[1]"], 1.2 * s["links-per-element.museum[0]"]);
  // "the museum file has one polygon per element, k = n".
  EXPECT_EQ(s["patches"], s["elements"]);

  // "Change the cluster tolerance to move both lines up or down: their slopes stay far below 2."
  const test::RanStep loose =
      test::runStepWithFigure("hierarchical", kFigure, [](StepParameters& p) { p.clusterTolerance = 0.2; });
  for (const char* name : {"museum", "factory-hall"}) {
    const std::string key = name;
    EXPECT_LT(loose["links." + key + "[2]"], s["links." + key + "[2]"]) << key;
    EXPECT_LT(loose["links-slope." + key], 1.5) << key;
  }
}

TEST(SceneLinks, AListedSceneThatDoesNotExistIsAnErrorAtItsLine) {
  const auto dir = std::filesystem::temp_directory_path() / "rt-scene-links-test";
  std::filesystem::create_directories(dir);
  const auto file = dir / "x.md";
  std::ofstream(file)
      << "---\ntitle: X\norder: 4\n---\n\n## Links\n\n```step\nscene: museum-1k.obj\n"
         "stage: scaling\nscenes: museum-1k.obj, no-such-scene.obj\nviews: links\nfigure: links\n```\n";
  const std::string message =
      test::inputErrorOf([&] { loadLesson(file.string(), test::repoFolders().scenes); });
  EXPECT_NE(message.find("x.md:11"), std::string::npos) << message;
  EXPECT_NE(message.find("no-such-scene.obj"), std::string::npos) << message;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rt::lesson
