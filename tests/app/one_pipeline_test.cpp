// The app and the command line compute a step through the same pipeline: every step of every lesson gives
// the same numbers in both, and the app runs a step once when it is opened (the replay of the solver's
// iterations comes from that run, not from a second solve).
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTest>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "app/lesson_session.h"
#include "app_test_support.h"
#include "core/formfactor/formfactor_method.h"
#include "core/refine/constrained_triangulation.h"
#include "lesson/step_numbers.h"
#include "lesson/step_result.h"
#include "lesson/step_settings.h"
#include "support/test_paths.h"

using namespace rt::app;

namespace {

// numbers.json of `radiosity lesson render`: one line per step, `{"step": k, "numbers": {...}}`.
std::map<int, std::string> readNumbers(const std::filesystem::path& file) {
  std::map<int, std::string> steps;
  std::ifstream in(file);
  const std::string head = "{\"step\": ", middle = ", \"numbers\": ";
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == ',') line.pop_back();
    if (line.rfind(head, 0) != 0) continue;
    const auto at = line.find(middle);
    const int step = std::stoi(line.substr(head.size(), at - head.size()));
    steps[step] = line.substr(at + middle.size(), line.size() - at - middle.size() - 1);
  }
  return steps;
}

}  // namespace

TEST(OnePipeline, TheAppComputesEveryStepAsTheCommandLineDoes) {
  RT_REQUIRE_DISPLAY();
  const std::string out = rt::test::scratchDir("one-pipeline");
  std::string log;
  ASSERT_EQ(rt::test::runCommand(rt::test::cliPath() + " lesson render --all --quick --root " +
                                     rt::test::sourcePath("") + " --output " + out,
                                 &log),
            0)
      << log;
  auto window = test::makeWindow();
  LessonLibrary& library = *window->library();
  int compared = 0;
  for (int l = 0; l < static_cast<int>(library.lessons().size()); ++l) {
    const auto& lesson = library.lessons()[static_cast<std::size_t>(l)];
    const auto cli = readNumbers(std::filesystem::path(out) / lesson.id / "numbers.json");
    for (const auto& step : lesson.steps) {
      auto it = cli.find(step.index);
      if (it == cli.end()) continue;  // skipped by the command line (a method this build does not have)
      const PipelineResult r =
          library.runStep(l, step.index, step.parameters, CompareChoice{}, rt::noProgress());
      ASSERT_NE(r.stepResult, nullptr);
      const auto& stepResult = *static_cast<const rt::lesson::StepResult*>(r.stepResult.get());
      EXPECT_EQ(rt::lesson::stepNumbersJson(stepResult), it->second)
          << lesson.id << " step " << step.index << " (" << step.title << ")";
      ++compared;
    }
  }
  EXPECT_GT(compared, 60);
}

// Opening a solving step runs it once: its replayable iterations come with it.
TEST(OnePipeline, TheAppRunsAStepOnceAndReplaysThatRun) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int lesson = window->library()->indexOf("gathering");
  ASSERT_GE(lesson, 0);
  const auto& steps = window->library()->lessons()[static_cast<std::size_t>(lesson)].steps;
  int solveStep = -1;
  for (const auto& s : steps)
    if (s.stage == rt::lesson::Stage::Solve && solveStep < 0) solveStep = s.index;
  ASSERT_GE(solveStep, 0);
  const int runsBefore = window->library()->stepRuns();
  ASSERT_TRUE(window->openStep(lesson, solveStep)) << window->lastError().toStdString();
  EXPECT_EQ(window->library()->stepRuns(), runsBefore + 1);
  const PipelineResult* r = window->result();
  ASSERT_NE(r, nullptr);
  ASSERT_GT(r->history.size(), 1u);
  // The last replayed iteration is the solution shown.
  EXPECT_TRUE(r->history.back().B.isApprox(r->B, 1e-12));
}

// The app registers what the command line registers: the exact method and CGAL's constrained triangulation
// for discontinuity meshing (the app used to mesh discontinuity steps with the fallback cuts).
TEST(OnePipeline, TheAppHasTheOptionalMethodsTheCommandLineHas) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const auto methods = rt::formFactorMethodNames();
  EXPECT_NE(std::find(methods.begin(), methods.end(), "exact"), methods.end());
  EXPECT_NE(rt::constrainedTriangulatorName().find("CGAL"), std::string::npos)
      << rt::constrainedTriangulatorName();
}

// A sweep sets the knob each method declares: the Nusselt analog's segments, the hemicube's resolution.
TEST(OnePipeline, ASweepSetsTheKnobTheMethodReads) {
  const rt::lesson::StepParameters p;
  EXPECT_EQ(rt::lesson::formFactorOptionsFor(p, "nusselt", 32).samples, 32);
  EXPECT_EQ(rt::lesson::formFactorOptionsFor(p, "hemicube", 32).hemicubeResolution, 32);
  EXPECT_EQ(rt::lesson::formFactorOptionsFor(p, "raycast", 32).samples, 32);
  rt::lesson::StepParameters q;
  q.formFactorTolerance = 1e-3;
  EXPECT_EQ(rt::lesson::formFactorOptionsFor(q, "quadrature", 0).tolerance, 1e-3);
  EXPECT_EQ(rt::lesson::formFactorOptionsFor(p, "quadrature", 0).tolerance, 0.0);  // the method's own
  EXPECT_DOUBLE_EQ(rt::accuracyKnobOf("exact").applied({}, 1e-4).tolerance,
                   rt::accuracyKnobOf("exact").field == rt::AccuracyKnob::Field::Tolerance
                       ? 1e-4
                       : rt::FormFactorOptions{}.tolerance);
}

// Going back to a step seen a moment ago shows it from memory: no second run, and at once, whatever the
// step cost (an adaptive mesh takes seconds). A changed control is a new computation; its old value is
// remembered too.
TEST(OnePipeline, ARevisitedStepIsShownFromMemory) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true);
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_TRUE(window->openLesson("meshing", 1));
  ASSERT_TRUE(window->waitUntilIdle(120000));
  const PipelineResult* first = window->result();
  ASSERT_NE(first, nullptr);
  const Eigen::Index elements = static_cast<Eigen::Index>(first->mesh->size());
  ASSERT_TRUE(window->nextStep());
  ASSERT_TRUE(window->waitUntilIdle(120000));
  // The step after it, computed ahead while the reader reads, is not the revisit's run.
  ASSERT_TRUE(window->waitUntilPrefetched(120000));
  const int runs = window->library()->stepRuns();
  QElapsedTimer timer;
  timer.start();
  ASSERT_TRUE(window->previousStep());
  ASSERT_TRUE(window->waitUntilIdle(120000));
  const qint64 ms = timer.elapsed();
  ASSERT_TRUE(window->waitUntilPrefetched(120000));  // the step after it is in memory: nothing to compute
  EXPECT_EQ(window->library()->stepRuns(), runs) << "the step was computed again";
  ASSERT_NE(window->result(), nullptr);
  EXPECT_EQ(static_cast<Eigen::Index>(window->result()->mesh->size()), elements);
  EXPECT_EQ(window->currentStep(), 1);
  EXPECT_LT(ms, 1000) << "a revisit took " << ms << " ms";
  RecordProperty("revisit_ms", static_cast<int>(ms));
  std::printf("revisit of meshing step 2: %lld ms\n", static_cast<long long>(ms));
}
