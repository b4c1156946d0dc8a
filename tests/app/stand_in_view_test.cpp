// The 3D view of a large mesh while the camera moves, as the reader moves it: during a drag with the mouse or
// a turn of the wheel the view draws the coarse stand-in (viz/stand_in_mesh.h), after the release (or once
// the wheel rests) the full mesh; a small scene is always drawn in full; a recolouring reaches the
// stand-in's colours, and the stand-in's frame shows the colours of the still frame, never black; mesh edges
// go with the full mesh. The timings at a million elements are AppScaleBenchmark's
// (scale_benchmark_test.cpp).
#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkMapper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <QApplication>
#include <QMouseEvent>
#include <QTest>
#include <QWheelEvent>
#include <array>
#include <set>
#include <vector>

#include "app/scene_view.h"
#include "app_test_support.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "support/test_paths.h"
#include "viz/mesh_edges.h"
#include "viz/stand_in_mesh.h"

using namespace rt;
using namespace rt::app;

namespace {

// The Cornell box (19 polygons) cut n x n: n = 80 gives 121,600 quads, 243,200 triangles, over the
// threshold; n = 10 stays far below it.
struct Box {
  explicit Box(int n) : scene(loadScene(rt::test::sourcePath("scenes/cornell-box.obj"))) {
    MeshOptions options;
    options.mode = MeshOptions::Mode::Count;
    options.count = n;
    mesh = buildMesh(scene, options);
    B = mesh.emission;
    for (Eigen::Index e = 0; e < B.rows(); ++e)
      B.row(e) += mesh.reflectance.row(e) * (1.0 + 0.3 * std::sin(0.01 * static_cast<double>(e)));
  }
  Scene scene;
  Mesh mesh;
  RgbField B;
};

// The inputs of the mappers that drew during `action` (a mapper announces each draw with StartEvent).
std::set<vtkDataObject*> drawnDuring(SceneView& view, const std::function<void()>& action) {
  std::set<vtkDataObject*> drawn;
  auto callback = vtkSmartPointer<vtkCallbackCommand>::New();
  callback->SetClientData(&drawn);
  callback->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    static_cast<std::set<vtkDataObject*>*>(client)->insert(
        static_cast<vtkMapper*>(caller)->GetInputDataObject(0, 0));
  });
  std::vector<std::pair<vtkMapper*, unsigned long>> observed;
  vtkActorCollection* actors = view.renderer()->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
    if (vtkMapper* mapper = actor->GetMapper())
      observed.emplace_back(mapper, mapper->AddObserver(vtkCommand::StartEvent, callback));
  action();
  for (auto [mapper, tag] : observed) mapper->RemoveObserver(tag);
  return drawn;
}

// Processes the posted paint; the read-back waits for the frame.
QImage finishFrame(SceneView& view) {
  QApplication::processEvents();
  return view.grabFramebuffer();
}

void sendMouse(SceneView& view, QEvent::Type type, QPoint at, Qt::MouseButtons buttons) {
  QMouseEvent event(type, QPointF(at), view.mapToGlobal(QPointF(at)), Qt::LeftButton, buttons,
                    Qt::NoModifier);
  QApplication::sendEvent(&view, &event);
}

void sendWheel(SceneView& view, QPoint at, int delta) {
  QWheelEvent event(QPointF(at), view.mapToGlobal(QPointF(at)), QPoint(), QPoint(0, delta), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(&view, &event);
}

// Mean colour of an image (0..255 per channel) and the share of its pixels that are near black.
std::array<double, 4> meanAndBlack(const QImage& image) {
  std::array<double, 4> out{};
  const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
  for (int y = 0; y < rgb.height(); ++y)
    for (int x = 0; x < rgb.width(); ++x) {
      const QRgb p = rgb.pixel(x, y);
      out[0] += qRed(p), out[1] += qGreen(p), out[2] += qBlue(p);
      if (qRed(p) + qGreen(p) + qBlue(p) < 30) out[3] += 1;
    }
  for (double& value : out) value /= static_cast<double>(rgb.width()) * rgb.height();
  return out;
}

struct Drag {
  std::set<vtkDataObject*> drawnMoving, drawnStill;
  bool movingDuringDrag = false, movingAfter = true;
  QImage lastMovingFrame, stillFrame;  // the same camera
};

// Press at the centre, three moves of 20 px with the left button held (each painted), release.
Drag dragAcross(SceneView& view) {
  Drag drag;
  const QPoint centre(view.width() / 2, view.height() / 2);
  drag.drawnMoving = drawnDuring(view, [&] {
    sendMouse(view, QEvent::MouseButtonPress, centre, Qt::LeftButton);
    for (int k = 1; k <= 3; ++k) {
      sendMouse(view, QEvent::MouseMove, centre + QPoint(20 * k, 0), Qt::LeftButton);
      drag.lastMovingFrame = finishFrame(view);
    }
  });
  drag.movingDuringDrag = view.inMotion();
  drag.drawnStill = drawnDuring(view, [&] {
    sendMouse(view, QEvent::MouseButtonRelease, centre + QPoint(60, 0), Qt::NoButton);
    drag.stillFrame = finishFrame(view);
  });
  drag.movingAfter = view.inMotion();
  return drag;
}

std::unique_ptr<SceneView> showView(const Box& box) {
  auto view = std::make_unique<SceneView>();
  view->resize(640, 480);
  view->show();
  EXPECT_TRUE(QTest::qWaitForWindowExposed(view.get()));
  view->setScene(&box.mesh, box.B, box.scene.camera.value_or(Camera{}), true);
  finishFrame(*view);
  return view;
}

void expectSameLook(const Drag& drag) {
  // The stand-in's frame and the still frame from the same camera: the same colours on the whole (the
  // stand-in's are means of the mesh's corners), and nothing black that is not black in the mesh's frame.
  const auto moving = meanAndBlack(drag.lastMovingFrame), still = meanAndBlack(drag.stillFrame);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(moving[c], still[c], 6.0) << "channel " << c;
  EXPECT_LT(moving[3], still[3] + 0.01);
}

}  // namespace

TEST(StandInView, ADragDrawsTheStandInAndTheStillFrameTheFullMesh) {
  RT_REQUIRE_DISPLAY();
  const Box box(80);
  ASSERT_GT(viz::triangleCount(box.mesh), viz::kStandInAboveTriangles);
  auto view = showView(box);
  vtkPolyData* full = view->displayedPolyData();
  vtkPolyData* standIn = view->standInPolyData();
  ASSERT_NE(standIn, nullptr);
  EXPECT_LT(standIn->GetNumberOfPolys(), static_cast<vtkIdType>(viz::triangleCount(box.mesh) / 2));

  const Drag drag = dragAcross(*view);
  EXPECT_TRUE(drag.movingDuringDrag);
  EXPECT_EQ(drag.drawnMoving.count(standIn), 1u);
  EXPECT_EQ(drag.drawnMoving.count(full), 0u);
  EXPECT_FALSE(drag.movingAfter);
  EXPECT_EQ(drag.drawnStill.count(full), 1u);
  EXPECT_EQ(drag.drawnStill.count(standIn), 0u);
  expectSameLook(drag);
  EXPECT_EQ(view->geometryBuilds(), 1);  // moving and resting build nothing
}

TEST(StandInView, TheWheelDrawsTheStandInUntilItRestsAndAClickPicksOnTheFullMesh) {
  RT_REQUIRE_DISPLAY();
  const Box box(80);
  auto view = showView(box);
  vtkPolyData* full = view->displayedPolyData();
  vtkPolyData* standIn = view->standInPolyData();
  const QPoint centre(view->width() / 2, view->height() / 2);
  const auto zooming = drawnDuring(*view, [&] {
    for (int k = 0; k < 2; ++k) {
      sendWheel(*view, centre, 120);
      finishFrame(*view);
    }
  });
  EXPECT_TRUE(view->inMotion());
  EXPECT_EQ(zooming.count(standIn), 1u);
  EXPECT_EQ(zooming.count(full), 0u);
  const auto resting = drawnDuring(*view, [&] {
    QTest::qWait(SceneView::kSettleMilliseconds + 150);
    finishFrame(*view);
  });
  EXPECT_FALSE(view->inMotion());
  EXPECT_EQ(resting.count(full), 1u);
  EXPECT_EQ(resting.count(standIn), 0u);

  // A click just after a wheel step: the motion ends and the pick finds an element of the full mesh.
  int picked = -1;
  QObject::connect(view.get(), &SceneView::elementPicked, [&picked](int e) { picked = e; });
  sendWheel(*view, centre, -120);
  finishFrame(*view);
  ASSERT_TRUE(view->inMotion());
  QTest::mouseClick(view.get(), Qt::LeftButton, Qt::NoModifier, centre);
  EXPECT_FALSE(view->inMotion());
  EXPECT_GE(picked, 0);
  EXPECT_LT(picked, static_cast<int>(box.mesh.size()));
}

TEST(StandInView, ASmallSceneNeverGetsAStandIn) {
  RT_REQUIRE_DISPLAY();
  const Box box(10);
  ASSERT_LT(viz::triangleCount(box.mesh), viz::kStandInAboveTriangles);
  auto view = showView(box);
  EXPECT_EQ(view->standInPolyData(), nullptr);
  const Drag drag = dragAcross(*view);
  EXPECT_EQ(drag.drawnMoving.count(view->displayedPolyData()), 1u);
  EXPECT_EQ(drag.drawnStill.count(view->displayedPolyData()), 1u);
}

// Mesh edges are the elements' (viz/mesh_edges.h): drawn with the full mesh, moving or still, never over the
// stand-in, whose triangles are not the elements.
TEST(StandInView, MeshEdgesGoWithTheFullMeshAndNotWithTheStandIn) {
  RT_REQUIRE_DISPLAY();
  for (int n : {10, 80}) {
    SCOPED_TRACE(n);
    const Box box(n);
    auto view = showView(box);
    view->setShowEdges(true);
    ASSERT_NE(view->meshEdges(), nullptr);
    vtkPolyData* edges = view->meshEdges()->polyData();
    const Drag drag = dragAcross(*view);
    EXPECT_EQ(drag.drawnMoving.count(edges), n == 10 ? 1u : 0u);
    EXPECT_EQ(drag.drawnStill.count(edges), 1u);
    EXPECT_GT(view->meshEdges()->shownEdges(), 0u);
    view->setShowEdges(false);
    EXPECT_EQ(view->meshEdges(), nullptr);
  }
}

TEST(StandInView, RecolouringReachesTheStandInWithoutRebuildingIt) {
  RT_REQUIRE_DISPLAY();
  const Box box(80);
  auto view = showView(box);
  vtkPolyData* standIn = view->standInPolyData();
  auto colours = [standIn] {
    auto* array = vtkUnsignedCharArray::SafeDownCast(standIn->GetPointData()->GetScalars());
    return std::vector<unsigned char>(array->GetPointer(0),
                                      array->GetPointer(0) + 3 * array->GetNumberOfTuples());
  };
  const vtkMTimeType cellsTime = standIn->GetPolys()->GetMTime();
  const std::vector<unsigned char> first = colours();

  // Another iteration's radiosity (bluer), then another tone map, then smooth shading.
  RgbField bluer = box.B;
  bluer.col(2) *= 3.0;
  view->setRadiosity(bluer);
  const std::vector<unsigned char> second = colours();
  EXPECT_NE(second, first);
  viz::SceneViewOptions options = view->viewOptions();
  options.image.toneMap = viz::ToneMap::Reinhard;
  view->setViewOptions(options);
  const std::vector<unsigned char> third = colours();
  EXPECT_NE(third, second);
  options.image.smooth = true;
  view->setViewOptions(options);
  EXPECT_NE(colours(), third);

  EXPECT_EQ(view->standInPolyData(), standIn);
  EXPECT_EQ(standIn->GetPolys()->GetMTime(), cellsTime);
  EXPECT_EQ(view->geometryBuilds(), 1);
  expectSameLook(dragAcross(*view));
}
