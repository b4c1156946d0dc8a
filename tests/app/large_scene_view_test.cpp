// The 3D view with many elements, as the reader uses it: a click picks the element under the cursor (the
// same one a picker testing every cell finds), the replay and the display keys recolour the cells in place
// (one polydata per mesh, never rebuilt for a step or a tone map), and a large scene the reader opens keeps
// one element per polygon and is solved by local lines. The timings at a million elements are
// AppScaleBenchmark's (scale_benchmark_test.cpp).
#include <gtest/gtest.h>

#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <fstream>
#include <vector>

#include "app/iteration_player.h"
#include "app/parameter_panel.h"
#include "app/scene_view.h"
#include "app_test_support.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "viz/display_pipeline.h"

using namespace rt;
using namespace rt::app;

namespace {

// A closed box room 4 x 3 x 5 (x, y up, z), each wall cut into cells x cells quads facing inwards, a light in
// the middle of the ceiling: 6 cells^2 polygons.
void writeGridRoom(const std::string& path, int cells) {
  std::ofstream obj(path + ".obj"), mtl(path + ".mtl");
  mtl << "newmtl white\nKd 0.6 0.6 0.6\nnewmtl red\nKd 0.6 0.1 0.1\nnewmtl light\nKd 0 0 0\nKe 40 40 40\n";
  obj << "mtllib " << QFileInfo(QString::fromStdString(path + ".mtl")).fileName().toStdString() << "\n";
  const Vec3 size(4, 3, 5);
  int next = 1;
  // A wall: origin o, edge vectors u and v (u x v points into the room).
  auto wall = [&](const char* name, Vec3 o, Vec3 u, Vec3 v, bool ceiling) {
    for (int i = 0; i < cells; ++i)
      for (int j = 0; j < cells; ++j) {
        const bool light =
            ceiling && std::abs(i - cells / 2) < cells / 6 && std::abs(j - cells / 2) < cells / 6;
        obj << "g " << (light ? "light" : name) << "\nusemtl "
            << (light                         ? "light"
                : std::string(name) == "left" ? "red"
                                              : "white")
            << "\n";
        for (auto [a, b] : {std::pair(i, j), {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}) {
          const Vec3 p = o + u * (double(a) / cells) + v * (double(b) / cells);
          obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << "\n";
        }
        obj << "f " << next << ' ' << next + 1 << ' ' << next + 2 << ' ' << next + 3 << "\n";
        next += 4;
      }
  };
  const double X = size.x(), Y = size.y(), Z = size.z();
  wall("floor", {0, 0, 0}, {0, 0, Z}, {X, 0, 0}, false);
  wall("ceiling", {0, Y, 0}, {X, 0, 0}, {0, 0, Z}, true);
  wall("back", {0, 0, 0}, {X, 0, 0}, {0, Y, 0}, false);
  wall("front", {0, 0, Z}, {0, Y, 0}, {X, 0, 0}, false);
  wall("left", {0, 0, 0}, {0, Y, 0}, {0, 0, Z}, false);
  wall("right", {X, 0, 0}, {0, 0, Z}, {0, Y, 0}, false);
}

// The cell a picker that tests every cell finds at widget pixel `p`: the reference for the view's pick.
int pickEveryCell(SceneView& view, QPoint p) {
  auto picker = vtkSmartPointer<vtkCellPicker>::New();
  picker->SetTolerance(0.0005);
  const double ratio = view.devicePixelRatioF();
  if (!picker->Pick(p.x() * ratio, (view.height() - 1 - p.y()) * ratio, 0, view.renderer())) return -1;
  return static_cast<int>(picker->GetCellId());
}

std::vector<unsigned char> coloursOf(SceneView& view) {
  auto* colours =
      vtkUnsignedCharArray::SafeDownCast(view.displayedPolyData()->GetPointData()->GetArray("colour"));
  return std::vector<unsigned char>(colours->GetPointer(0),
                                    colours->GetPointer(0) + 3 * colours->GetNumberOfTuples());
}

}  // namespace

// A click at each of these points of the view (fractions of its width and height).
const std::vector<QPointF> kClicks = {{0.5, 0.5}, {0.23, 0.31}, {0.71, 0.64}, {0.12, 0.88}, {0.93, 0.07}};

// 100k elements in a view of its own: clicks pick what a full search picks, colours change in place.
TEST(LargeSceneView, ClicksPickTheElementUnderTheCursorAndRecolouringKeepsTheCells) {
  RT_REQUIRE_DISPLAY();
  QTemporaryDir dir;
  const std::string path = QDir(dir.path()).filePath("room").toStdString();
  writeGridRoom(path, 129);
  const Scene scene = loadScene(path + ".obj");
  const Mesh mesh = buildMesh(scene);
  ASSERT_EQ(mesh.size(), 6u * 129 * 129);
  RgbField first = mesh.emission, second = mesh.emission;
  for (Eigen::Index e = 0; e < first.rows(); ++e) {
    first.row(e) += Eigen::RowVector3d(1.0, 0.8, 0.6) * (1 + std::sin(0.001 * e));
    second.row(e) += Eigen::RowVector3d(0.5, 0.9, 1.2) * (1 + std::cos(0.002 * e));
  }

  SceneView view;
  view.resize(800, 600);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  Camera camera;  // from inside the room towards its back wall
  camera.position = Vec3(2.0, 1.5, 4.8);
  camera.target = Vec3(2.0, 1.5, 0.0);
  camera.up = Vec3::UnitY();
  camera.fovYDegrees = 60;
  view.setScene(&mesh, first, camera, true);
  view.grabFramebuffer();
  ASSERT_NE(view.displayedPolyData(), nullptr);
  EXPECT_EQ(view.displayedPolyData()->GetNumberOfCells(), static_cast<vtkIdType>(mesh.size()));
  EXPECT_EQ(view.geometryBuilds(), 1);

  int picked = -1;
  QObject::connect(&view, &SceneView::elementPicked, [&picked](int e) { picked = e; });
  for (const QPointF& at : kClicks) {
    const QPoint p(static_cast<int>(at.x() * view.width()), static_cast<int>(at.y() * view.height()));
    const int expected = pickEveryCell(view, p);
    ASSERT_GE(expected, 0) << "nothing under " << p.x() << ", " << p.y();
    picked = -1;
    QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, p);
    EXPECT_EQ(picked, expected) << "at " << p.x() << ", " << p.y();
  }
  // The centre of the view is the back wall, which faces the camera.
  QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, QPoint(view.width() / 2, view.height() / 2));
  ASSERT_GE(picked, 0);
  EXPECT_GT(mesh.elements[static_cast<std::size_t>(picked)].normal.z(), 0.99);

  // A new iteration, then smooth shading: new colours in the same cells.
  vtkPolyData* cells = view.displayedPolyData();
  const std::vector<unsigned char> before = coloursOf(view);
  view.setRadiosity(second);
  view.grabFramebuffer();
  const std::vector<unsigned char> stepped = coloursOf(view);
  EXPECT_NE(stepped, before);
  viz::SceneViewOptions options = view.viewOptions();
  options.image.smooth = true;
  view.setViewOptions(options);
  view.grabFramebuffer();
  EXPECT_NE(coloursOf(view), stepped);
  EXPECT_EQ(view.displayedPolyData(), cells);
  EXPECT_EQ(view.geometryBuilds(), 1);
  EXPECT_GE(view.colourUpdates(), 2);
  // A click still picks what a full search picks.
  const QPoint p(view.width() / 3, view.height() / 2);
  const int expected = pickEveryCell(view, p);
  QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, p);
  EXPECT_EQ(picked, expected);
}

// The window with a scene of 5,400 polygons, opened as the reader opens one: one element per polygon, local
// lines; a click names the element, N steps the replay and the tone map control recolours, neither solving
// again nor rebuilding the view's cells.
TEST(LargeSceneView, TheWindowPicksStepsAndRecoloursWithoutRebuildingOrSolving) {
  RT_REQUIRE_DISPLAY();
  QTemporaryDir dir;
  const std::string path = QDir(dir.path()).filePath("room").toStdString();
  writeGridRoom(path, 30);
  auto window = test::makeWindow();
  window->activateWindow();
  QApplication::setActiveWindow(window.get());
  ASSERT_TRUE(window->openScene(QString::fromStdString(path + ".obj"))) << window->lastError().toStdString();
  const PipelineResult* result = window->result();
  ASSERT_NE(result, nullptr);
  EXPECT_EQ(result->mesh->size(), 5400u);
  EXPECT_EQ(result->solverName, "local-lines");
  ASSERT_GE(result->history.size(), 2u);
  // The budget chosen for the scene, 1000 rays per element, shows as such (not as "automatic").
  auto* rays = window->parameterPanel()->findChild<QSpinBox*>("control-rays-per-iteration");
  ASSERT_NE(rays, nullptr);
  EXPECT_EQ(rays->value(), 5400000);
  SceneView* view = window->primaryView();
  view->grabFramebuffer();
  EXPECT_EQ(view->displayedPolyData()->GetNumberOfCells(), 5400);
  const int builds = view->geometryBuilds();

  // Off the middle, where the even grid puts edges between cells (either cell would be right there).
  const QPoint at(view->width() * 37 / 100, view->height() * 41 / 100);
  const int expected = pickEveryCell(*view, at);
  ASSERT_GE(expected, 0);
  QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, at);
  EXPECT_EQ(view->highlighted(), std::vector<int>{expected});
  auto* status = window->findChild<QLabel*>("statusMessage");
  ASSERT_NE(status, nullptr);
  EXPECT_TRUE(status->text().startsWith(QString("element %1 ").arg(expected)))
      << status->text().toStdString();

  // Back to the first iteration with the player's first button, then N.
  QAbstractButton* firstButton = nullptr;
  for (auto* button : window->player()->findChildren<QAbstractButton*>())
    if (button->text() == "|<") firstButton = button;
  ASSERT_NE(firstButton, nullptr);
  QTest::mouseClick(firstButton, Qt::LeftButton);
  EXPECT_EQ(window->player()->current(), 0);
  view->grabFramebuffer();
  const std::vector<unsigned char> firstColours = coloursOf(*view);
  QTest::keyClick(window.get(), Qt::Key_N);
  EXPECT_EQ(window->player()->current(), 1);
  view->grabFramebuffer();
  EXPECT_TRUE(view->viewData().B.isApprox(result->history[1].B));
  const std::vector<unsigned char> secondColours = coloursOf(*view);
  EXPECT_NE(secondColours, firstColours);

  // The tone map, chosen in its control with the keyboard: recoloured, not solved again.
  auto* toneMap = window->parameterPanel()->findChild<QComboBox*>("control-tone-map");
  ASSERT_NE(toneMap, nullptr);
  const QString was = toneMap->currentText();
  toneMap->setFocus();
  QTest::keyClick(toneMap, was == "linear" ? Qt::Key_Down : Qt::Key_Up);
  ASSERT_NE(toneMap->currentText(), was);
  test::waitForApply();
  EXPECT_EQ(window->result(), result) << "a tone map solved the scene again";
  EXPECT_EQ(view->viewOptions().image.toneMap, viz::toneMapFromName(toneMap->currentText().toStdString()));
  view->grabFramebuffer();
  EXPECT_NE(coloursOf(*view), secondColours);
  EXPECT_EQ(view->geometryBuilds(), builds);
  EXPECT_EQ(view->highlighted(), std::vector<int>{expected});
}
