// The web edition's session (src/web), natively: it computes what the pipeline computes, reports bad files
// and settings as the programs do (file, line, key), and keeps F across a change of reflectance or light.
#include <gtest/gtest.h>

#include <algorithm>
#include <span>

#include "core/io/scene_loader.h"
#include "core/pipeline/pipeline.h"
#include "support/test_paths.h"
#include "web/web_session.h"
#include "web/web_settings.h"

namespace rt::web {
namespace {

void loadCornellBox(WebSession& session) {
  session.putFile("cornell-box.json", test::readFile(test::sourcePath("scenes/cornell-box.json")));
  EXPECT_EQ(session.load("cornell-box.json"), "");
}

TEST(WebSession, SolvesAsThePipelineDoes) {
  WebSession session;
  loadCornellBox(session);
  ASSERT_EQ(session.configure(R"({"subdivide": 2, "solver": "gauss-seidel", "method": "analytic"})"), "");
  const std::string summary = session.run();
  EXPECT_EQ(summary.find("error"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"camera\":{\"fov\""), std::string::npos) << summary;

  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  PipelineSettings settings;
  settings.mesh.mode = MeshOptions::Mode::Count;
  settings.mesh.count = 2;
  settings.method = "analytic";
  settings.solver = "gauss-seidel";
  Pipeline pipeline;
  const PipelineOutput out = pipeline.run(scene, settings);
  ASSERT_EQ(session.elements(), static_cast<int>(out.mesh->size()));
  const std::vector<double> B = session.radiosity(-1);
  ASSERT_EQ(B.size(), 3 * out.mesh->size());
  for (Eigen::Index i = 0; i < out.solve.B.rows(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(B[std::size_t(3 * i + c)], out.solve.B(i, c));
  // Every iteration is there to scrub through, and the last one is the answer.
  ASSERT_GT(session.iterations(), 1);
  EXPECT_EQ(session.radiosity(session.iterations() - 1), B);
  EXPECT_EQ(session.residuals().size(), std::size_t(session.iterations()));
  EXPECT_EQ(session.trianglePositions().size(), 9 * session.triangleElements().size());
  EXPECT_EQ(session.csv().substr(0, 30), "element,patch,surface,area,B_r");
  const std::vector<double> row = session.formFactorRow(3);
  ASSERT_EQ(row.size(), out.mesh->size());
  for (std::size_t j = 0; j < row.size(); ++j) EXPECT_EQ(row[j], (*out.F)(3, Eigen::Index(j)));
  EXPECT_TRUE(session.formFactorRow(-1).empty());
}

TEST(WebSession, AReflectanceChangeSolvesAgainWithTheSameFormFactors) {
  WebSession session;
  loadCornellBox(session);
  ASSERT_EQ(session.configure(R"({"subdivide": 2, "solver": "jacobi"})"), "");
  session.run();
  const std::vector<double> before = session.radiosity(-1);
  ASSERT_EQ(session.configure(R"({"subdivide": 2, "solver": "jacobi", "lightScale": 2,
                                  "reflectance": {"floor": [0.1, 0.1, 0.1]}})"),
            "");
  const std::string summary = session.run();
  EXPECT_NE(summary.find("\"formFactorsReused\":true"), std::string::npos) << summary;
  EXPECT_NE(session.radiosity(-1), before);
}

TEST(WebSession, ABadSceneIsReportedWithItsFileAndLine) {
  WebSession session;
  session.putFile("room.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  const std::string message = session.load("room.obj");
  EXPECT_NE(message.find("room.obj:4"), std::string::npos) << message;
  session.putFile("room.json", "{\"surfaces\": [}");
  EXPECT_NE(session.load("room.json").find("room.json"), std::string::npos);
  EXPECT_NE(session.load("missing.json").find("missing.json"), std::string::npos);
}

TEST(WebSession, BadSettingsNameTheirKey) {
  WebSession session;
  loadCornellBox(session);
  EXPECT_NE(session.configure(R"({"subdivid": 2})").find("\"subdivid\""), std::string::npos);
  EXPECT_NE(session.configure(R"({"solver": "magic"})").find("solver"), std::string::npos);
  EXPECT_NE(session.configure(R"({"reflectance": {"floor": [1.5, 0, 0]}})").find("reflectance.floor"),
            std::string::npos);
  EXPECT_NE(session.configure(R"({"reflectance": {"ceiling_fan": [0.5, 0.5, 0.5]}})").find("ceiling_fan"),
            std::string::npos);
  EXPECT_EQ(session.configure(R"({"maxEdge": 200})"), "");
}

TEST(WebSettings, WrittenSettingsReadBackToTheSameRun) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  PipelineSettings read;
  ASSERT_EQ(readSettings(R"({"maxEdge": 120, "splitAtContacts": true, "method": "hemicube", "resolution": 64,
                             "solver": "southwell", "tolerance": 1e-7, "iterations": 50, "seed": 9,
                             "lightScale": 1.5, "reflectance": {"floor": [0.2, 0.3, 0.4]}})",
                         scene, read),
            "");
  PipelineSettings again;
  ASSERT_EQ(readSettings(settingsJson(read), scene, again), "");
  EXPECT_EQ(settingsJson(again), settingsJson(read));
  EXPECT_EQ(again.mesh.mode, MeshOptions::Mode::MaxEdge);
  EXPECT_TRUE(again.mesh.splitAtContacts);
  EXPECT_EQ(again.formFactors.hemicubeResolution, 64);
  EXPECT_EQ(again.solverOptions.maxIterations, 50);
  EXPECT_EQ(again.reflectance.at("floor")[1], 0.3);
}

TEST(WebSession, AnObjFindsItsMaterialLibrary) {
  WebSession session;
  session.putFile("cornell-box.obj", test::readFile(test::sourcePath("scenes/cornell-box.obj")));
  session.putFile("cornell-box.mtl", test::readFile(test::sourcePath("scenes/cornell-box.mtl")));
  ASSERT_EQ(session.load("cornell-box.obj"), "");
  ASSERT_EQ(session.configure(R"({"noSubdivide": true, "solver": "gauss-seidel", "method": "analytic"})"),
            "");
  const std::string summary = session.run();
  EXPECT_EQ(summary.find("error"), std::string::npos) << summary;
  EXPECT_GT(session.elements(), 10);
}

// The pages spread F's rows over workers: rows computed in other sessions, in blocks, and handed to one that
// solves give what that session computes alone, bit for bit, with F counted as computed for the run.
TEST(WebSession, RowsComputedApartSolveAsTheWholeMatrixDoes) {
  const std::string settings = R"({"subdivide": 4, "solver": "gauss-seidel", "method": "hemicube"})";
  WebSession alone, gathering, helper;
  for (WebSession* s : {&alone, &gathering, &helper}) {
    loadCornellBox(*s);
    ASSERT_EQ(s->configure(settings), "");
  }
  alone.run();
  const int n = gathering.rowPlan();
  ASSERT_EQ(n, alone.elements());
  // Blocks by turns from a helper's session and computed by the gathering session itself, as the pages'
  // workers share them.
  for (int begin = 0, k = 0; begin < n; begin += 37, ++k) {
    const int end = std::min(n, begin + 37);
    if (k % 2 == 1) {
      ASSERT_TRUE(gathering.fillFormFactorRows(begin, end));
      continue;
    }
    const std::span<const double> rows = helper.formFactorRows(begin, end);
    const std::span<double> target = gathering.rowsToFill(begin, end);
    ASSERT_EQ(target.size(), rows.size());
    std::copy(rows.begin(), rows.end(), target.begin());
  }
  EXPECT_TRUE(gathering.rowsToFill(0, n + 1).empty());
  EXPECT_FALSE(gathering.fillFormFactorRows(n - 1, n + 1));
  const std::string summary = gathering.run();
  EXPECT_NE(summary.find("\"formFactorsReused\":false"), std::string::npos) << summary;
  EXPECT_EQ(gathering.radiosity(-1), alone.radiosity(-1));
  EXPECT_EQ(gathering.iterations(), alone.iterations());
  for (int i : {0, n / 2, n - 1}) EXPECT_EQ(gathering.formFactorRow(i), alone.formFactorRow(i));
  // With F now cached, or for a method whose rows are not independent, there is nothing to spread.
  EXPECT_EQ(gathering.rowPlan(), 0);
  ASSERT_EQ(gathering.configure(R"({"subdivide": 4, "solver": "gauss-seidel", "method": "analytic"})"), "");
  EXPECT_EQ(gathering.rowPlan(), 0);
}

}  // namespace
}  // namespace rt::web
