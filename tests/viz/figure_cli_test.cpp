// Image tests of `radiosity figure`, F3D-style: every view rendered by the CLI from the Cornell box and
// compared to a baseline PNG in tests/baselines (mean absolute difference per channel below a threshold),
// plus structural checks of the vector formats. RT_UPDATE_BASELINES=1 rewrites the baselines (look at them
// before committing).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>

#include "support/test_paths.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

// Mean absolute difference per channel (0-255) that still counts as the same picture: covers font
// rasterisation and GL driver differences, not a changed colour or a missing element.
constexpr double kThreshold = 4.0;

std::string cornellBox() {
  return test::sourcePath("scenes/cornell-box.json");
}

int runFigure(const std::string& arguments, const std::string& output, std::string* log = nullptr) {
  return test::runCommand(
      test::cliPath() + " figure " + cornellBox() + " " + arguments + " --output " + output, log);
}

struct ViewCase {
  std::string name;       // baseline file: <name>.png
  std::string arguments;  // view and options; @SOURCE@ stands for the repository
  bool deterministic = true;
  // Drawn from the exact reference (visibility) or meshed by its CGAL triangulation (discontinuity): a build
  // without it cannot draw the view, or draws another mesh.
  bool needsExact = false;
};

std::string expandSource(std::string arguments) {
  const std::string key = "@SOURCE@";
  for (auto at = arguments.find(key); at != std::string::npos; at = arguments.find(key))
    arguments.replace(at, key.size(), test::sourcePath(""));
  return arguments;
}

// Test names and failure messages show the view, not the bytes of the struct.
void PrintTo(const ViewCase& view, std::ostream* os) {
  *os << view.name << " (" << view.arguments << ")";
}

class FigureView : public ::testing::TestWithParam<ViewCase> {};

TEST_P(FigureView, MatchesItsBaselineAndIsNotBlank) {
  const ViewCase& view = GetParam();
  const std::string output = test::scratchDir("figure_" + view.name) + "/" + view.name + ".png";
  std::string log;
  const int status = runFigure(expandSource(view.arguments) + " --width 480 --height 360", output, &log);
  if (view.needsExact && log.find("needs the exact reference") != std::string::npos)
    GTEST_SKIP() << "built without the exact reference";
  ASSERT_EQ(status, 0) << log;
  const vizt::PngStats stats = vizt::pngStats(output);
  EXPECT_EQ(stats.width, 480);
  EXPECT_EQ(stats.height, 360);
  EXPECT_GT(stats.stddev, 15.0) << "looks blank";
  EXPECT_GT(stats.mean[0] + stats.mean[1] + stats.mean[2], 60.0) << "looks black";
  if (!view.deterministic) return;
  if (view.needsExact && view.arguments.find("discontinuity") != std::string::npos &&
      log.find("CGAL") == std::string::npos)
    return;  // the fallback triangulation: another mesh than the baseline's
  const double difference = vizt::compareWithBaseline(output, view.name + ".png");
  ASSERT_GE(difference, 0.0) << "no baseline tests/baselines/" << view.name << ".png of the same size";
  EXPECT_LT(difference, kThreshold) << output;
}

INSTANTIATE_TEST_SUITE_P(
    Views, FigureView,
    ::testing::Values(
        ViewCase{"scene_radiosity", "--view scene"},
        ViewCase{"scene_smooth_edges", "--view scene --subdivide 3 --smooth --edges --tone-map reinhard"},
        ViewCase{"scene_reflectance", "--view scene --colour reflectance"},
        ViewCase{"scene_element", "--view scene --colour element --subdivide 2 --edges"},
        ViewCase{"scene_unshot", "--view scene --colour unshot --log"},
        ViewCase{"scene_error", "--view scene --colour error --colour-map cividis"},
        ViewCase{"scene_error_absolute", "--view scene --colour error --error absolute"},
        ViewCase{"scene_adaptive_mesh", "--view scene --mesh adaptive --max-elements 400 --edges"},
        ViewCase{"formfactor", "--view formfactor --log"}, ViewCase{"hemicube_faces", "--view hemicube"},
        ViewCase{"hemicube_delta", "--view hemicube --colour delta"},
        ViewCase{"hemicube_3d", "--view hemicube --part 3d"},
        ViewCase{"nusselt_hemisphere", "--view nusselt"},
        ViewCase{"nusselt_disk", "--view nusselt --part disk"}, ViewCase{"rays", "--view rays"},
        ViewCase{"matrix", "--view matrix --row 3"}, ViewCase{"matrix_k", "--view matrix --matrix K --log"},
        ViewCase{"convergence", "--view convergence"}, ViewCase{"energy", "--view energy"},
        ViewCase{"runtime_error", "--view runtime-error", false},
        ViewCase{"runtime_error_table",
                 "--view runtime-error --input @SOURCE@/tests/viz/data/bench-formfactors.csv"},
        ViewCase{"visibility", "--view visibility", true, true}, ViewCase{"links", "--view links"},
        ViewCase{"links_element", "--view links --element 300"},
        ViewCase{"links_formfactor", "--view links --link-colour formfactor --link-tolerance 0.05"},
        ViewCase{"discontinuity", "--view discontinuity", true, true}),
    [](const ::testing::TestParamInfo<ViewCase>& info) { return info.param.name; });

class VectorFigure : public ::testing::TestWithParam<std::string> {};

TEST_P(VectorFigure, SvgAndPdfAreTrueVectors) {
  const std::string dir = test::scratchDir("vector_" + GetParam());
  std::string log;
  ASSERT_EQ(runFigure("--view " + GetParam() + " --width 600 --height 450", dir + "/f.svg", &log), 0) << log;
  ASSERT_EQ(runFigure("--view " + GetParam() + " --width 600 --height 450", dir + "/f.pdf", &log), 0) << log;
  const std::string svg = vizt::readFile(dir + "/f.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_TRUE(svg.find("<path") != std::string::npos || svg.find("<polygon") != std::string::npos);
  EXPECT_EQ(svg.find("<image"), std::string::npos) << "a raster in a vector figure";
  const std::string pdf = vizt::readFile(dir + "/f.pdf");
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  EXPECT_GT(pdf.size(), 1500u);
  EXPECT_EQ(pdf.find("/Subtype /Image"), std::string::npos) << "a raster in a vector figure";
}

INSTANTIATE_TEST_SUITE_P(TwoDimensional, VectorFigure,
                         ::testing::Values("matrix", "nusselt", "hemicube", "convergence", "energy"));

TEST(FigureCommand, ThreeDimensionalPdfEmbedsARaster) {
  const std::string dir = test::scratchDir("figure_pdf3d");
  std::string log;
  ASSERT_EQ(runFigure("--view scene --width 400 --height 300", dir + "/scene.pdf", &log), 0) << log;
  const std::string pdf = vizt::readFile(dir + "/scene.pdf");
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  EXPECT_NE(pdf.find("/Subtype /Image"), std::string::npos);
}

TEST(FigureCommand, UnknownExtensionIsRejectedWithThePath) {
  std::string log;
  EXPECT_NE(runFigure("--view scene", "/tmp/figure.bmp", &log), 0);
  EXPECT_NE(log.find("figure.bmp"), std::string::npos) << log;
}

TEST(FigureCommand, InputBelongsToTheRuntimeErrorView) {
  std::string log;
  EXPECT_NE(runFigure("--view scene --input " + test::sourcePath("tests/viz/data/bench-formfactors.csv"),
                      test::scratchDir("figure_bad") + "/x.png", &log),
            0);
  EXPECT_NE(log.find("--input"), std::string::npos) << log;
}

TEST(FigureCommand, WithoutADisplayItIsAClearErrorNotACrash) {
  // VTK's X window aborts the process when no X server answers; the figure must say what to do instead.
  const std::string dir = test::scratchDir("figure_no_display");
  std::string log;
  const int status = test::runCommand("env -u DISPLAY " + test::cliPath() + " figure " + cornellBox() +
                                          " --view scene --output " + dir + "/x.png",
                                      &log);
  EXPECT_EQ(status, 1) << log;  // an error exit, not SIGABRT
  EXPECT_NE(log.find("cannot render: no X display (DISPLAY is not set)"), std::string::npos) << log;
  EXPECT_NE(log.find("xvfb-run"), std::string::npos) << log;
}

TEST(FigureCommand, AMalformedTimingTableNamesItsLine) {
  const std::string dir = test::scratchDir("figure_bad_table");
  std::ofstream(dir + "/t.csv") << "method,parameter,seconds,rms_error\nhemicube,16,0.1\n";
  std::string log;
  EXPECT_NE(runFigure("--view runtime-error --input " + dir + "/t.csv", dir + "/x.png", &log), 0);
  EXPECT_NE(log.find("t.csv:2"), std::string::npos) << log;
}

TEST(FigureCommand, ElementOutOfRangeIsAnError) {
  std::string log;
  EXPECT_NE(runFigure("--view formfactor --element 999", test::scratchDir("figure_bad") + "/x.png", &log), 0);
  EXPECT_NE(log.find("--element"), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::viz
