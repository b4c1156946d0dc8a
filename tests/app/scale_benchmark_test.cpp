// The app with a large solved scene (docs/benchmarks.md, "The app at a million elements"): the time to build
// the 3D view (its coarse stand-in included, when the mesh has one), the frame time of a rotation dragged
// with the mouse (the stand-in's frames) and of the still frame after it (the full mesh), a pick (a click on
// the view: the element outlined and named in the status bar), a recolour (the tone map changed in the
// parameters) and a step to the next iteration (the N key), each until the frame is on screen. Disabled by
// default: the scenes are generated and the million-element museum takes about a minute to solve. Run under
// the build lock:
//   python3 scenes/tools/make_large_scenes.py museum 250000   (and 1000000; they land in scenes/)
//   scenes/tools/bench_app.sh out/app-bench scenes/museum-50k.obj scenes/museum-250k.obj ...
// which sets RT_APP_BENCH_SCENES (the scene files) and RT_APP_BENCH_SCREENSHOTS (a folder for a PNG of the
// window per scene, and of the 3D view at the drag's last frame and after the release: the same camera) and
// runs app_tests
// --gtest_also_run_disabled_tests --gtest_filter='AppScaleBenchmark.*' under Xvfb.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QMouseEvent>
#include <QTest>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <vtkPolyData.h>

#include "app/iteration_player.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "support/test_paths.h"

using namespace rt::app;

namespace {

// Resident and peak resident memory of this process (MB), from /proc.
double procStatusMb(const char* key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key, 0) == 0) return std::atof(line.c_str() + std::strlen(key)) / 1024.0;
  return 0;
}

// Processes the posted paint and waits until the view's frame is complete (a read-back of the framebuffer
// cannot finish before the GL work before it).
void finishFrame(SceneView* view) {
  QApplication::processEvents();
  view->grabFramebuffer();
}

double millisecondsOf(const std::function<void()>& action) {
  QElapsedTimer timer;
  timer.start();
  action();
  return static_cast<double>(timer.nsecsElapsed()) / 1e6;
}

void sendMouse(QWidget* widget, QEvent::Type type, QPoint at, Qt::MouseButtons buttons) {
  QMouseEvent event(type, QPointF(at), widget->mapToGlobal(QPointF(at)), Qt::LeftButton, buttons,
                    Qt::NoModifier);
  QApplication::sendEvent(widget, &event);
}

}  // namespace

TEST(AppScaleBenchmark, DISABLED_LargeMuseum) {
  RT_REQUIRE_DISPLAY();
  const char* list = std::getenv("RT_APP_BENCH_SCENES");
  std::istringstream scenes(list ? list : rt::test::sourcePath("scenes/museum-50k.obj"));
  const char* shots = std::getenv("RT_APP_BENCH_SCREENSHOTS");
  constexpr int kFrames = 40;
  std::printf(
      "| elements | view (px) | open and solve (s) | display build (ms) | stand-in build (ms) | stand-in "
      "triangles | drag frame (ms) | slowest drag frame (ms) | still frame (ms) | first pick (ms) | pick "
      "(ms) | recolour (ms) | smooth "
      "(ms) | next iteration (ms) | polydata (MB) | resident (MB) | peak (MB) |\n");
  for (std::string path; scenes >> path;) {
    auto window = test::makeWindow(false);
    window->resize(1600, 1000);
    window->activateWindow();
    QApplication::setActiveWindow(window.get());
    QApplication::processEvents();
    QElapsedTimer open;
    open.start();
    ASSERT_TRUE(window->openScene(QString::fromStdString(path))) << window->lastError().toStdString();
    const double openSeconds = static_cast<double>(open.elapsed()) / 1e3;
    const PipelineResult* result = window->result();
    ASSERT_NE(result, nullptr);
    SceneView* view = window->primaryView();
    finishFrame(view);

    // The display alone: the same mesh and B handed to the view again.
    view->setScene(nullptr, {}, result->camera, false);
    finishFrame(view);
    const double build = millisecondsOf([&] {
      view->setScene(result->mesh.get(), result->B, result->camera, true);
      finishFrame(view);
    });
    // What the view's cells and colours take (the renderer's copies in the GL driver come on top).
    const double viewMemory = static_cast<double>(view->displayedPolyData()->GetActualMemorySize()) / 1024;

    // A rotation as the reader drags it: press, kFrames moves of 6 px with the button held, each painted
    // (the stand-in's frames, when the mesh has one); then the release and its still frame (the full mesh).
    const QPoint centre(view->width() / 2, view->height() / 2);
    const QString base =
        shots ? QString("%1/%2").arg(shots, QFileInfo(QString::fromStdString(path)).baseName()) : QString();
    if (shots) QDir().mkpath(shots);
    double frame = 0, slowest = 0;
    for (int k = 0; k <= kFrames; ++k) {
      const double move = millisecondsOf([&] {
        sendMouse(view, k == 0 ? QEvent::MouseButtonPress : QEvent::MouseMove, centre + QPoint(6 * k, 0),
                  Qt::LeftButton);
        if (k == kFrames) finishFrame(view);  // the last move's frame is on screen
        QApplication::processEvents();
      });
      frame += move;
      slowest = std::max(slowest, move);
      if (shots && k == kFrames)
        view->grabFramebuffer().save(base + "-drag.png");  // the still frame's camera
    }
    frame /= kFrames;
    const double still = millisecondsOf([&] {
      sendMouse(view, QEvent::MouseButtonRelease, centre + QPoint(6 * kFrames, 0), Qt::NoButton);
      finishFrame(view);
    });
    if (shots) view->grabFramebuffer().save(base + "-still.png");
    vtkPolyData* standIn = view->standInPolyData();

    window->resetView();
    finishFrame(view);
    const double pick = millisecondsOf([&] {
      QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, centre);
      finishFrame(view);
    });
    EXPECT_EQ(view->highlighted().size(), 1u) << "nothing picked at the centre of " << path;
    const double secondPick = millisecondsOf([&] {
      QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(view->width() / 5, 0));
      finishFrame(view);
    });

    rt::lesson::StepParameters p = window->parameterPanel()->parameters();
    p.toneMap = p.toneMap == "reinhard" ? "linear" : "reinhard";
    const double recolour = millisecondsOf([&] {
      window->applyParameters(p);
      finishFrame(view);
    });
    p.smooth = true;
    const double smooth = millisecondsOf([&] {
      window->applyParameters(p);
      finishFrame(view);
    });

    IterationPlayer* player = window->player();
    player->setCurrent(0);
    finishFrame(view);
    const double step = millisecondsOf([&] {
      QTest::keyClick(window.get(), Qt::Key_N);
      finishFrame(view);
    });
    EXPECT_EQ(player->current(), std::min(1, player->iterationCount() - 1));

    std::printf(
        "| %zu | %d x %d | %.1f | %.0f | %.0f | %lld | %.1f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f "
        "| %.0f "
        "| "
        "%.0f | %.0f |\n",
        result->mesh->size(), view->width(), view->height(), openSeconds, build,
        view->standInBuildMilliseconds(), standIn ? static_cast<long long>(standIn->GetNumberOfPolys()) : 0LL,
        frame, slowest, still, pick, secondPick, recolour, smooth, step, viewMemory, procStatusMb("VmRSS:"),
        procStatusMb("VmHWM:"));
    std::fflush(stdout);
    if (shots) {
      p.smooth = false;
      window->applyParameters(p);
      player->setCurrent(player->iterationCount() - 1);
      saveScreenshot(*window,
                     QString("%1/%2.png").arg(shots, QFileInfo(QString::fromStdString(path)).baseName()));
    }
  }
}
