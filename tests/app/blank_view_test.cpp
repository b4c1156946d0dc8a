// Every 3D view of a lesson shows something to learn from: the closed furnace cube is seen from inside, its
// walls apart by their edges and its ceiling not dark, and the two squares of the form-factor steps both
// show, each in its own colour.
#include <gtest/gtest.h>

#include <QImage>
#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>

#include "app/lesson_session.h"
#include "app/scene_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "support/test_paths.h"
#include "viz/vtk_render.h"

using namespace rt::app;

namespace {

struct ShownStep {
  std::string lesson;
  int step = 0;
};

// The steps of `lessons` whose scene file starts with `scenePrefix`.
std::vector<ShownStep> stepsOn(MainWindow& window, const std::vector<std::string>& lessons,
                               const std::string& scenePrefix) {
  std::vector<ShownStep> steps;
  for (const std::string& id : lessons) {
    const int index = window.library()->indexOf(id);
    if (index < 0) continue;
    for (const auto& step : window.library()->lessons()[static_cast<std::size_t>(index)].steps)
      if (step.scene.rfind(scenePrefix, 0) == 0) steps.push_back({id, step.index});
  }
  return steps;
}

// Opens the step and grabs its 3D view (kept in the scratch folder to look at); a null image when the step
// shows no mesh.
QImage openShown(MainWindow& window, const ShownStep& s) {
  if (!window.openLesson(QString::fromStdString(s.lesson), s.step) || !window.waitUntilIdle()) return {};
  SceneView* view = window.primaryView();
  if (!view->isVisible() || !view->hasMesh()) return {};
  const QImage image = grabWindow(*view);
  image.save(QString::fromStdString(rt::test::scratchDir("blank-views") + "/" + s.lesson + "-" +
                                    std::to_string(s.step) + ".png"));
  return image;
}

// Calls `check` with every step of `steps` that shows its 3D view, and the view's image; returns how many.
int forEachShown(MainWindow& window, const std::vector<ShownStep>& steps,
                 const std::function<void(const ShownStep&, const QImage&)>& check) {
  int shown = 0;
  for (const ShownStep& s : steps) {
    SCOPED_TRACE(s.lesson + " step " + std::to_string(s.step));
    const QImage image = openShown(window, s);
    if (image.isNull()) continue;
    ++shown;
    check(s, image);
  }
  return shown;
}

double luminance(QRgb c) {
  return 0.2126 * qRed(c) + 0.7152 * qGreen(c) + 0.0722 * qBlue(c);
}

}  // namespace

TEST(BlankViews, TheFurnaceIsSeenFromInsideWithItsWallsApart) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const auto steps =
      stepsOn(*window, {"rendering-equation", "radiosity-matrix", "numerical-stability"}, "furnace-cube");
  ASSERT_GE(steps.size(), 5u);
  const int checked = forEachShown(*window, steps, [&](const ShownStep& s, const QImage& image) {
    const PixelStatistics stats = pixelStatistics(image);
    std::cout << s.lesson << " step " << s.step << ": luminance " << stats.meanLuminance << " +- "
              << stats.stdDevLuminance << ", " << stats.distinctColours << " colours\n";
    // One flat colour has no spread. Near rho = 1 every face is nearly as bright as the light, as the text
    // says, so the walls stand apart by their edges alone: dark lines across the view.
    EXPECT_GE(stats.distinctColours, 3);
    int edgePixels = 0, pixels = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x, ++pixels)
        edgePixels += luminance(image.pixel(x, y)) < stats.meanLuminance - 60;
    EXPECT_GT(edgePixels, pixels / 1000) << "no edges between the walls";
    // Inside the box no background shows: the camera is in the room.
    const QRgb background = qRgb(static_cast<int>(rt::viz::kBackground[0] * 255 + 0.5),
                                 static_cast<int>(rt::viz::kBackground[1] * 255 + 0.5),
                                 static_cast<int>(rt::viz::kBackground[2] * 255 + 0.5));
    int backgroundPixels = 0;
    for (int y = 0; y < image.height(); y += 4)
      for (int x = 0; x < image.width(); x += 4)
        if (std::abs(luminance(image.pixel(x, y)) - luminance(background)) < 2) ++backgroundPixels;
    EXPECT_LT(backgroundPixels, (image.width() / 4) * (image.height() / 4) / 20);
    // The ceiling (the light of the one-light furnace) is not dark: mesh edges are lines, never a face in the
    // edge colour, even where a face reaches behind the camera.
    SceneView* view = window->primaryView();
    double ceiling = 0, rest = 0;
    int ceilingPoints = 0, restPoints = 0;
    const double sx = double(image.width()) / view->width(), sy = double(image.height()) / view->height();
    for (int y = 2; y < view->height(); y += 8)
      for (int x = 2; x < view->width(); x += 8) {
        const int element = view->pickElement(QPoint(x, y));
        if (element < 0) continue;
        const QPoint p(std::min(image.width() - 1, int(x * sx)), std::min(image.height() - 1, int(y * sy)));
        const bool up = view->mesh()->elements[static_cast<std::size_t>(element)].normal.y() < -0.9;
        (up ? ceiling : rest) += luminance(image.pixel(p));
        ++(up ? ceilingPoints : restPoints);
      }
    ASSERT_GT(ceilingPoints, 20) << "the ceiling is out of view";
    ASSERT_GT(restPoints, 0);
    std::cout << "  ceiling luminance " << ceiling / ceilingPoints << ", the other walls "
              << rest / restPoints << "\n";
    EXPECT_GT(ceiling / ceilingPoints, 0.6 * rest / restPoints) << "a dark ceiling";
  });
  EXPECT_GE(checked, 2) << "no furnace step showed its 3D view";
}

TEST(BlankViews, BothSquaresShowWhereTheTextDiscussesTwo) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  std::vector<ShownStep> steps = stepsOn(*window, {"form-factor", "nusselt-analog"}, "parallel-squares");
  for (const ShownStep& s : stepsOn(*window, {"form-factor", "nusselt-analog"}, "perpendicular-squares"))
    steps.push_back(s);
  ASSERT_GE(steps.size(), 4u);
  const int checked = forEachShown(*window, steps, [&](const ShownStep& s, const QImage& image) {
    SceneView* view = window->primaryView();
    // Which square each point of a grid over the view shows, and its mean luminance there.
    std::map<int, std::pair<double, int>> seen;  // patch -> (sum of luminance, pixels)
    const double sx = double(image.width()) / view->width(), sy = double(image.height()) / view->height();
    for (int y = 2; y < view->height(); y += 8)
      for (int x = 2; x < view->width(); x += 8) {
        const int element = view->pickElement(QPoint(x, y));
        if (element < 0) continue;
        const int patch = view->mesh()->elements[static_cast<std::size_t>(element)].patch;
        const QPoint p(std::min(image.width() - 1, int(x * sx)), std::min(image.height() - 1, int(y * sy)));
        seen[patch].first += luminance(image.pixel(p));
        ++seen[patch].second;
      }
    std::cout << s.lesson << " step " << s.step << ":";
    for (const auto& [patch, sum] : seen)
      std::cout << " patch " << patch << " " << sum.second << " points, luminance " << sum.first / sum.second;
    std::cout << "\n";
    ASSERT_EQ(seen.size(), 2u) << "both squares in view";
    for (const auto& [patch, sum] : seen) EXPECT_GE(sum.second, 20) << "square " << patch << " is a sliver";
    const double a = seen[0].first / seen[0].second, b = seen[1].first / seen[1].second;
    EXPECT_GT(std::abs(a - b), 10.0) << "the two squares in one colour";
    const double backgroundLuminance =
        255 * (0.2126 * rt::viz::kBackground[0] + 0.7152 * rt::viz::kBackground[1] +
               0.0722 * rt::viz::kBackground[2]);
    EXPECT_GT(std::min(std::abs(a - backgroundLuminance), std::abs(b - backgroundLuminance)), 10.0)
        << "a square in the background's colour";
  });
  EXPECT_GE(checked, 2) << "no squares step showed its 3D view";
}
