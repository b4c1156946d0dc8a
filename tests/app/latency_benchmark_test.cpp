// How long the reader waits, as a table for docs/benchmarks.md: Page Down to the next step's result
// on screen, Page Up back to a step just seen (shown from memory), and a control changed through its widget
// to the new picture, on steps of up to 1,000 elements. Driven through the real window with keys, timed
// until the window is idle and painted. Disabled by default (it walks many steps and prints a table rather
// than asserting a machine's speed). Run it idle, under Xvfb:
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/release/tests/app_tests
//     --gtest_also_run_disabled_tests --gtest_filter='AppLatencyBenchmark.*'
#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QTest>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "app/lesson_session.h"
#include "app/parameter_panel.h"
#include "app_test_support.h"

using namespace rt::app;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double maximum(const std::vector<double>& v) {
  return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
}

// Milliseconds from `action` to the window being idle with its events (the repaint) processed.
double millisecondsUntilShown(MainWindow& window, const std::function<void()>& action) {
  QElapsedTimer timer;
  timer.start();
  action();
  window.waitUntilIdle(600000);
  QApplication::processEvents();
  return static_cast<double>(timer.nsecsElapsed()) / 1e6;
}

bool isOrdinary(const rt::lesson::Step& step) {
  using rt::lesson::Stage;
  // The stages that measure, path-trace or refine are long by design: timed apart, not as "ordinary".
  return step.stage != Stage::Benchmark && step.stage != Stage::PathTrace && step.stage != Stage::Refine &&
         step.stage != Stage::Scaling && step.stage != Stage::Exact;
}

}  // namespace

TEST(AppLatencyBenchmark, DISABLED_StepsRevisitsAndControls) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow(/*threaded=*/true, /*quick=*/false);
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  std::vector<double> ordinary, long_, revisit, control;
  const auto& lessons = window->library()->lessons();
  for (const char* id : {"local-vs-global", "form-factor", "hemicube", "radiosity-matrix", "gathering",
                         "shooting", "cornell-box", "meshing", "stochastic"}) {
    const int l = window->library()->indexOf(id);
    ASSERT_GE(l, 0) << id;
    ASSERT_TRUE(window->openStep(l, 0));
    window->waitUntilIdle(600000);
    const auto& steps = lessons[static_cast<std::size_t>(l)].steps;
    for (std::size_t s = 1; s < steps.size(); ++s) {
      const double next =
          millisecondsUntilShown(*window, [&] { QTest::keyClick(window.get(), Qt::Key_PageDown); });
      (isOrdinary(steps[s]) ? ordinary : long_).push_back(next);
      const PipelineResult* r = window->result();
      const bool small = r && r->mesh && r->mesh->size() <= 1000 && r->mesh->size() > 0;
      // The first of the controls a reader changes most that the step offers: the light, else a reflectance.
      for (const auto& [key, value] : {std::pair{"light-scale", "1.5"}, std::pair{"reflectance", "0.5"}}) {
        if (!small || !window->parameterPanel()->offers(key)) continue;
        QWidget* editor = window->parameterPanel()->editor(key);
        // Typed and Enter pressed (applied at once, not after the pause that typing alone waits out).
        editor->setFocus();
        QTest::mouseClick(editor, Qt::LeftButton);
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, value);
        control.push_back(millisecondsUntilShown(*window, [&] { QTest::keyClick(editor, Qt::Key_Return); }));
        break;
      }
      revisit.push_back(millisecondsUntilShown(*window,
                                               [&] {
                                                 QTest::keyClick(window.get(), Qt::Key_PageUp);
                                                 window->waitUntilIdle(600000);
                                                 QTest::keyClick(window.get(), Qt::Key_PageDown);
                                               }) /
                        2);
    }
  }
  std::printf("| action | steps | median | largest |\n|---|---:|---:|---:|\n");
  std::printf("| next step (ordinary) | %zu | %.0f ms | %.0f ms |\n", ordinary.size(), median(ordinary),
              maximum(ordinary));
  std::printf("| next step (benchmark, path tracing, refinement, exact) | %zu | %.0f ms | %.0f ms |\n",
              long_.size(), median(long_), maximum(long_));
  std::printf("| revisited step (back or forward) | %zu | %.0f ms | %.0f ms |\n", revisit.size(),
              median(revisit), maximum(revisit));
  std::printf("| light or reflectance changed, <= 1,000 elements | %zu | %.0f ms | %.0f ms |\n",
              control.size(), median(control), maximum(control));
  EXPECT_FALSE(ordinary.empty());
}
