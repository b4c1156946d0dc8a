// A reader's own scene seen from inside: a Cornell box OBJ as the archives publish it (open front towards +z,
// y up, no camera) is looked into through its open side; the View menu's standard views and Reset view.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QTest>
#include <QTextBrowser>

#include "app/camera_views.h"
#include "app/scene_view.h"
#include "app/screenshot.h"
#include "app_test_support.h"
#include "core/io/scene_loader.h"

using namespace rt::app;

namespace {

const QString kBox = QString::fromStdString(RT_SOURCE_DIR "/tests/data/cornell-box-no-camera.obj");

rt::Vec3 viewDirection(const rt::Camera& c) {
  return (c.target - c.position).normalized();
}

}  // namespace

TEST(SceneCamera, AnOpenBoxIsSeenThroughItsOpenSide) {
  const rt::Scene scene = rt::loadScene(kBox.toStdString());
  ASSERT_FALSE(scene.camera.has_value());
  EXPECT_TRUE(openSide(scene).isApprox(rt::Vec3(0, 0, 1))) << openSide(scene).transpose();
  const rt::Camera c = sceneCamera(scene);
  EXPECT_GT(c.position.z(), scene.bounds().max().z()) << "outside the open side";
  EXPECT_TRUE(viewDirection(c).isApprox(rt::Vec3(0, 0, -1), 1e-9));
  EXPECT_TRUE(c.up.isApprox(rt::Vec3(0, 1, 0)));
}

TEST(SceneCamera, TheOpenedObjLooksLikeACornellBox) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(kBox)) << window->lastError().toStdString();
  SceneView* view = window->primaryView();
  QImage image = grabWindow(*window);
  QDir().mkpath(RT_BINARY_DIR "/tests/screenshots");
  image.save(RT_BINARY_DIR "/tests/screenshots/cornell-box-obj-no-camera.png");
  const QRect area = test::areaOf(window.get(), view);
  // From the open side the five walls fill the view: the left third is red, the right third green.
  auto mean = [&](double x0, double x1) {
    double r = 0, g = 0, n = 0;
    for (int y = area.top() + area.height() / 3; y < area.top() + 2 * area.height() / 3; ++y)
      for (int x = area.left() + static_cast<int>(x0 * area.width());
           x < area.left() + static_cast<int>(x1 * area.width()); ++x) {
        const QRgb p = image.pixel(x, y);
        r += qRed(p);
        g += qGreen(p);
        ++n;
      }
    return std::pair{r / n, g / n};
  };
  const auto [leftR, leftG] = mean(0.05, 0.2);
  const auto [rightR, rightG] = mean(0.8, 0.95);
  EXPECT_GT(leftR, 1.5 * leftG) << "the left wall is red";
  EXPECT_GT(rightG, 1.5 * rightR) << "the right wall is green";
  EXPECT_GT(pixelStatistics(image, area).meanLuminance, 20);
}

TEST(SceneCamera, StandardViewsAndResetFromTheKeys) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  ASSERT_TRUE(window->openScene(kBox));
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  QWidget* target = window.get();
  const rt::Camera start = window->primaryView()->currentCamera();
  QTest::keyClick(target, Qt::Key_7);
  EXPECT_TRUE(viewDirection(window->primaryView()->currentCamera()).isApprox(rt::Vec3(0, -1, 0), 1e-6));
  QTest::keyClick(target, Qt::Key_3);
  EXPECT_TRUE(viewDirection(window->primaryView()->currentCamera()).isApprox(rt::Vec3(-1, 0, 0), 1e-6));
  QTest::keyClick(target, Qt::Key_1);
  EXPECT_TRUE(viewDirection(window->primaryView()->currentCamera()).isApprox(rt::Vec3(0, 0, -1), 1e-6));
  QTest::keyClick(target, Qt::Key_R);
  EXPECT_LT((window->primaryView()->currentCamera().position - start.position).norm(), 1e-6);
}

// The lesson's Cornell box names its camera, at -z looking along +z: that is its front. The Front view looks
// into the box from there (it showed the back of the back wall when Front meant +z), Top has the front at the
// bottom, and Side is the right-hand side as seen from the front (-x, where the green wall stands).
TEST(SceneCamera, TheStandardViewsFaceTheSceneFromItsOwnFront) {
  const rt::Scene lesson = rt::loadScene(RT_SOURCE_DIR "/scenes/cornell-box.json");
  ASSERT_TRUE(lesson.camera.has_value());
  EXPECT_TRUE(frontDirection(lesson).isApprox(rt::Vec3(0, 0, -1))) << frontDirection(lesson).transpose();
  const rt::Camera front = standardCamera(lesson, StandardView::Front);
  EXPECT_TRUE(viewDirection(front).isApprox(rt::Vec3(0, 0, 1), 1e-9));
  EXPECT_LT(front.position.z(), lesson.bounds().min().z());
  const rt::Camera top = standardCamera(lesson, StandardView::Top);
  EXPECT_TRUE(viewDirection(top).isApprox(rt::Vec3(0, -1, 0), 1e-9));
  EXPECT_TRUE(top.up.isApprox(rt::Vec3(0, 0, 1))) << "the front (-z) at the bottom of the picture";
  const rt::Camera side = standardCamera(lesson, StandardView::Side);
  EXPECT_TRUE(viewDirection(side).isApprox(rt::Vec3(1, 0, 0), 1e-9));
  // Without a camera, the open side is the front; with neither, +z.
  EXPECT_TRUE(frontDirection(rt::loadScene(kBox.toStdString())).isApprox(rt::Vec3(0, 0, 1)));
  EXPECT_TRUE(frontDirection(rt::Scene{}).isApprox(rt::Vec3(0, 0, 1)));
}
