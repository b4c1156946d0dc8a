// How long the reader waits, as a table for docs/benchmarks.md: Page Down to the next step's result
// on screen, Page Up back to a step just seen (shown from memory), and a control changed through its widget
// to the new picture, on every step of up to 1,000 elements that offers one. Every step of every lesson,
// driven through the real window with keys, timed until the window is idle and painted; the steps over a
// target are listed first. Disabled by default (it walks every step and prints a table rather than asserting
// a machine's speed). Run it idle, under Xvfb:
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/release/tests/app_tests
//     --gtest_also_run_disabled_tests --gtest_filter='AppLatencyBenchmark.*'
// RT_LATENCY_LESSONS=id,id,... times only those lessons; RT_LATENCY_ALL=1 lists every step, not only those
// over a target.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QSpinBox>
#include <QTest>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
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

// The control a step offers that a reader changes first: the light, else a reflectance, else the first the
// step lists. Changed through its widget by one key (typed and Enter for a value field) and applied at
// once, not after the pause that typing alone waits out.
std::string changeFirstControl(MainWindow& window, const rt::lesson::Step& step) {
  ParameterPanel* panel = window.parameterPanel();
  std::vector<std::string> keys = {"light-scale", "reflectance"};
  keys.insert(keys.end(), step.controls.begin(), step.controls.end());
  for (const std::string& key : keys) {
    if (!panel->offers(key)) continue;
    QWidget* editor = panel->editor(key);
    editor->setFocus();
    if (key == "light-scale" || key == "reflectance") {
      QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
      QTest::keyClicks(editor, key == "light-scale" ? "1.5" : "0.5");
      QTest::keyClick(editor, Qt::Key_Return);
    } else if (auto* spin = qobject_cast<QAbstractSpinBox*>(editor)) {
      auto* ints = qobject_cast<QSpinBox*>(spin);
      auto* doubles = qobject_cast<QDoubleSpinBox*>(spin);
      const bool atTop =
          ints ? ints->value() >= ints->maximum() : doubles && doubles->value() >= doubles->maximum();
      QTest::keyClick(spin, atTop ? Qt::Key_Down : Qt::Key_Up);
      panel->applyNow();
    } else if (auto* box = qobject_cast<QComboBox*>(editor)) {
      QTest::keyClick(box, box->currentIndex() + 1 < box->count() ? Qt::Key_Down : Qt::Key_Up);
      panel->applyNow();
    } else if (auto* check = qobject_cast<QCheckBox*>(editor)) {
      QTest::mouseClick(check, Qt::LeftButton, {}, QPoint(8, check->height() / 2));
      panel->applyNow();
    } else {
      continue;
    }
    return key;
  }
  return {};
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
  // Every step over the targets, for the reader of the table to look into (or every step).
  const bool listAll = std::getenv("RT_LATENCY_ALL") != nullptr;
  std::printf("| lesson | step | next | revisit | control |\n");
  for (int l = 0; l < static_cast<int>(lessons.size()); ++l) {
    const auto& lesson = lessons[static_cast<std::size_t>(l)];
    if (const char* only = std::getenv("RT_LATENCY_LESSONS");
        only && ("," + std::string(only) + ",").find("," + lesson.id + ",") == std::string::npos)
      continue;
    ASSERT_TRUE(window->openStep(l, 0));
    window->waitUntilIdle(600000);
    const auto& steps = lesson.steps;
    for (std::size_t s = 1; s < steps.size(); ++s) {
      // The reader reads the step before turning the page: meanwhile the window computes the next one.
      window->waitUntilPrefetched(600000);
      const double next =
          millisecondsUntilShown(*window, [&] { QTest::keyClick(window.get(), Qt::Key_PageDown); });
      (isOrdinary(steps[s]) ? ordinary : long_).push_back(next);
      const PipelineResult* r = window->result();
      const bool small = r && r->mesh && r->mesh->size() <= 1000 && r->mesh->size() > 0;
      window->waitUntilPrefetched(600000);
      std::string key;
      double changed = 0;
      if (small && steps[s].stage != rt::lesson::Stage::Exercise) {
        changed = millisecondsUntilShown(*window, [&] { key = changeFirstControl(*window, steps[s]); });
        if (!key.empty()) control.push_back(changed);
      }
      const double back = millisecondsUntilShown(*window,
                                                 [&] {
                                                   QTest::keyClick(window.get(), Qt::Key_PageUp);
                                                   window->waitUntilIdle(600000);
                                                   QTest::keyClick(window.get(), Qt::Key_PageDown);
                                                 }) /
                          2;
      revisit.push_back(back);
      const bool over = (isOrdinary(steps[s]) && next > 300) || back > 200 || (!key.empty() && changed > 300);
      if (over || listAll)
        std::printf(
            "| %s | %zu%s | %.0f ms | %.0f ms | %s |\n", lesson.id.c_str(), s + 1,
            isOrdinary(steps[s]) ? "" : " (long)", next, back,
            key.empty() ? "" : (key + " " + std::to_string(static_cast<int>(changed)) + " ms").c_str());
    }
  }
  std::printf("\n| action | steps | median | largest |\n|---|---:|---:|---:|\n");
  std::printf("| next step (ordinary) | %zu | %.0f ms | %.0f ms |\n", ordinary.size(), median(ordinary),
              maximum(ordinary));
  std::printf(
      "| next step (long: benchmark, path tracing, refinement, scaling, exact) | %zu | %.0f ms | %.0f ms |\n",
      long_.size(), median(long_), maximum(long_));
  std::printf("| revisited step (back or forward) | %zu | %.0f ms | %.0f ms |\n", revisit.size(),
              median(revisit), maximum(revisit));
  std::printf("| a control changed, <= 1,000 elements | %zu | %.0f ms | %.0f ms |\n", control.size(),
              median(control), maximum(control));
  EXPECT_FALSE(ordinary.empty());
}
