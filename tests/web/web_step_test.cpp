// A lesson step in the web edition (src/web/web_step.h): the page's widgets are rows of the one table of
// step keys, a step's parameters reach the pipeline through the lesson layer's one mapping, and a value the
// app's panel refuses is refused with the same words.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/pipeline/pipeline.h"
#include "lesson/lesson_loader.h"
#include "lesson/step_keys.h"
#include "lesson/step_settings.h"
#include "support/test_paths.h"
#include "web/web_session.h"
#include "web/web_step.h"

namespace rt::web {
namespace {

using Json = nlohmann::json;

TEST(WebStep, WidgetsAreRowsOfTheStepKeyTable) {
  const Json rows =
      Json::parse(controlRowsJson({"solver", "subdivide", "method", "light-scale", "no-such-key"}));
  ASSERT_EQ(rows.size(), 4u);
  for (const Json& row : rows) {
    const lesson::StepKey* key = lesson::findStepKey(row["name"].get<std::string>());
    ASSERT_NE(key, nullptr);
    EXPECT_EQ(row["label"], key->label);
    EXPECT_EQ(row["min"], key->min);
    EXPECT_EQ(row["max"], key->max);
    EXPECT_EQ(row["default"], key->defaultText);
  }
  EXPECT_EQ(rows[0]["type"], "choice");
  EXPECT_EQ(rows[0]["choices"].get<std::vector<std::string>>(), lesson::findStepKey("solver")->allowed());
  EXPECT_EQ(rows[1]["type"], "int");
  // The form-factor methods this build can compute, as the app lists them.
  EXPECT_EQ(rows[2]["choices"].get<std::vector<std::string>>(), formFactorMethodNames());
}

TEST(WebStep, ALiveStepOffersItsControlsAndTheCommonOnes) {
  const lesson::Lesson cornell =
      lesson::loadLesson(test::sourcePath("lessons/cornell-box.md"), test::sourcePath("scenes"));
  bool sawBounces = false;
  for (const lesson::Step& step : cornell.steps) {
    if (step.stage != lesson::Stage::Bounces) continue;
    sawBounces = true;
    const std::vector<std::string> keys = liveControls(step);
    auto offers = [&](const std::string& k) { return std::find(keys.begin(), keys.end(), k) != keys.end(); };
    EXPECT_TRUE(offers("method") && offers("subdivide") && offers("seed") && offers("light-scale"));
    EXPECT_FALSE(offers("solver"));  // a bounces step adds the Neumann series' terms itself
    const bool declared =
        std::find(step.controls.begin(), step.controls.end(), "bounces") != step.controls.end();
    EXPECT_EQ(offers("bounces"), declared) << step.title;
  }
  EXPECT_TRUE(sawBounces);
  lesson::Step solve;
  solve.stage = lesson::Stage::Solve;
  solve.controls = {"tolerance", "reflectance.floor"};
  EXPECT_EQ(liveControls(solve), (std::vector<std::string>{"method", "solver", "subdivide", "seed",
                                                           "light-scale", "tolerance", "reflectance"}));
}

TEST(WebStep, AStepComputesWhatTheLessonLayerMapsItTo) {
  WebSession session;
  session.putFile("cornell-box.json", test::readFile(test::sourcePath("scenes/cornell-box.json")));
  ASSERT_EQ(session.load("cornell-box.json"), "");
  ASSERT_EQ(session.configureStep(R"({"stage": "solve", "parameters": {"subdivide": "2", "solver": "jacobi",
                                      "method": "analytic", "reflectance.floor": "0.3"}})"),
            "");
  const std::string summary = session.run();
  EXPECT_EQ(summary.find("error"), std::string::npos) << summary;

  lesson::StepParameters p;
  p.subdivide = 2;
  p.solver = "jacobi";
  p.method = "analytic";
  p.reflectance["floor"] = Rgb(0.3, 0.3, 0.3);
  Pipeline pipeline;
  const PipelineOutput out =
      pipeline.run(loadScene(test::sourcePath("scenes/cornell-box.json")), lesson::settingsFor(p, p.method));
  ASSERT_EQ(session.elements(), static_cast<int>(out.mesh->size()));
  const std::vector<double> B = session.radiosity(-1);
  for (Eigen::Index i = 0; i < out.solve.B.rows(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(B[std::size_t(3 * i + c)], out.solve.B(i, c));

  // A bounces step: one iteration per bounce.
  ASSERT_EQ(
      session.configureStep(R"({"stage": "bounces", "parameters": {"subdivide": "2", "bounces": "3"}})"), "");
  session.run();
  EXPECT_EQ(session.iterations(), 3);

  // F downloads as the NumPy file the matrix writer writes.
  const std::string npy = session.formFactorFile(MatrixFormat::Npy);
  ASSERT_GT(npy.size(), 10u);
  EXPECT_EQ(npy.substr(1, 5), "NUMPY");
  EXPECT_NE(npy.find("'shape': (" + std::to_string(session.elements())), std::string::npos);
  const std::string csv = session.formFactorFile(MatrixFormat::Csv);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), session.elements());
}

TEST(WebStep, ALightChangeScalesTheLastSolutionAsASolveWould) {
  const std::string box = test::readFile(test::sourcePath("scenes/cornell-box.json"));
  auto step = [](const std::string& solver, const std::string& light) {
    return R"({"stage": "solve", "parameters": {"subdivide": "3", "method": "analytic", "solver": ")" +
           solver + R"(", "light-scale": ")" + light + R"("}})";
  };
  for (const std::string solver : {"gauss-seidel", "southwell", "stochastic-jacobi"}) {
    WebSession changed, fresh;
    for (WebSession* s : {&changed, &fresh}) {
      s->putFile("cornell-box.json", box);
      ASSERT_EQ(s->load("cornell-box.json"), "");
    }
    ASSERT_EQ(changed.configureStep(step(solver, "1")), "");
    changed.run();
    ASSERT_EQ(changed.configureStep(step(solver, "2.5")), "");
    changed.run();
    ASSERT_EQ(fresh.configureStep(step(solver, "2.5")), "");
    fresh.run();
    ASSERT_EQ(changed.iterations(), fresh.iterations()) << solver;
    const std::vector<double> a = changed.radiosity(-1), b = fresh.radiosity(-1);
    const std::vector<double> a1 = changed.radiosity(0), b1 = fresh.radiosity(0);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(a[i], b[i], 1e-12 * std::max(1.0, std::abs(b[i]))) << solver << " element " << i / 3;
      EXPECT_NEAR(a1[i], b1[i], 1e-12 * std::max(1.0, std::abs(b1[i]))) << solver << " element " << i / 3;
    }
    EXPECT_EQ(changed.emission(), fresh.emission());
  }
}

TEST(WebStep, AValueTheAppRefusesIsRefusedNamingItsKey) {
  PipelineSettings settings;
  const std::string tooFine = readStep(R"({"parameters": {"subdivide": "100"}})", settings);
  EXPECT_NE(tooFine.find("subdivide"), std::string::npos) << tooFine;
  EXPECT_NE(readStep(R"({"parameters": {"solver": "magic"}})", settings).find("unknown solver 'magic'"),
            std::string::npos);
  EXPECT_NE(readStep(R"({"parameters": {"scene": "x.json"}})", settings).find("\"scene\""),
            std::string::npos);
  EXPECT_NE(readStep(R"({"stage": "hemicube"})", settings).find("stage"), std::string::npos);
  EXPECT_EQ(readStep(R"({"parameters": {"seed": 7, "light-scale": "2"}})", settings), "");
  EXPECT_EQ(settings.lightScale, 2);
  EXPECT_EQ(settings.solverOptions.seed, 7u);
}

}  // namespace
}  // namespace rt::web
