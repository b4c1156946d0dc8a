// A thread that keeps its offscreen window (the app's figure thread) draws every figure as a new window
// would, and hands the window out again only once no figure holds it.
#include <gtest/gtest.h>
#include <vtkRenderWindow.h>

#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "support/test_paths.h"
#include "viz/chart.h"
#include "viz/rays_view.h"
#include "viz/viz_test_support.h"
#include "viz/vtk_render.h"

namespace rt::viz {
namespace {

// A 3D figure through a faint room with depth peeling, a chart (a context view), and the 3D figure again
// at another size: what the figure thread draws one after another.
std::vector<std::string> drawFigures(const std::string& folder, const std::string& tag) {
  const Mesh mesh = vizt::openRoomMesh(2);
  const int last = static_cast<int>(mesh.size()) - 1;
  const RaySample rays = sampleRays(mesh, 0, last, 40);
  const Camera camera = vizt::openRoom().cameraOrDefault();
  Series curve{"residual", {}, {}};
  for (int k = 1; k <= 20; ++k) {
    curve.x.push_back(k);
    curve.y.push_back(std::pow(0.6, k));
  }
  ChartOptions chart;
  chart.title = "Residual";
  chart.logY = true;
  chart.width = 400;
  chart.height = 300;
  std::vector<std::string> files;
  for (const char* name : {"rays", "chart", "rays-wide", "chart-again"})
    files.push_back(folder + "/" + tag + "-" + name + ".png");
  RaysViewOptions view;
  view.size = {360, 240, 96.0};
  writeRaysFigure(mesh, camera, rays, view, files[0]);
  writeLineChart({curve}, chart, files[1]);
  view.size = {480, 260, 96.0};
  writeRaysFigure(mesh, camera, rays, view, files[2]);
  writeLineChart({curve}, chart, files[3]);
  return files;
}

TEST(OffscreenWindow, AKeptWindowDrawsEveryFigureAsANewOneWould) {
  const std::string folder = test::scratchDir("offscreen-window-kept");
  std::vector<std::string> fresh, kept;
  std::thread([&] { fresh = drawFigures(folder, "new"); }).join();
  std::thread([&] {
    keepOffscreenWindowsOnThisThread();
    kept = drawFigures(folder, "kept");
  }).join();
  ASSERT_EQ(fresh.size(), kept.size());
  for (std::size_t k = 0; k < fresh.size(); ++k)
    EXPECT_EQ(vizt::pngDifference(fresh[k], kept[k]), 0.0) << kept[k] << " differs from " << fresh[k];
}

TEST(OffscreenWindow, TheKeptWindowIsGivenAgainOnlyWhenNoFigureHoldsIt) {
  std::thread([] {
    keepOffscreenWindowsOnThisThread();
    const vtkRenderWindow* first = makeOffscreenWindow(64, 48).Get();
    auto again = makeOffscreenWindow(80, 60);
    EXPECT_EQ(again.Get(), first) << "the window no one holds is kept for the next figure";
    EXPECT_EQ(again->GetSize()[0], 80);
    auto other = makeOffscreenWindow(64, 48);
    EXPECT_NE(other.Get(), again.Get()) << "a window still drawn in is not given to another figure";
  }).join();
}

}  // namespace
}  // namespace rt::viz
