// The 3D view of a solved scene: elements coloured by radiosity, optional mesh edges, highlighted elements,
// and picking (a click names the element under the cursor). Two of them side by side make the compare mode;
// they share a camera through syncCameraFrom(). A large mesh (viz::wantsStandIn) is drawn as a coarse
// stand-in with the same colours while the camera moves (a drag, the wheel, a walkthrough), and in full on
// the still frame after the motion (viz/stand_in_mesh.h).
#pragma once

#include <memory>
#include <vector>

#include "app/vtk_widget.h"
#include "core/scene.h"
#include "viz/ray_tree_view.h"
#include "viz/scene_view.h"

class QTimer;
class vtkActor;
class vtkObject;
class vtkCellPicker;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkScalarBarActor;
class vtkTextActor;

namespace rt::viz {
class MeshEdgeLines;
}

namespace rt::app {

class StandInActor;

class SceneView : public VtkWidget {
  Q_OBJECT
 public:
  explicit SceneView(QWidget* parent = nullptr);
  ~SceneView() override;

  // A new mesh and its radiosity at once (the previous mesh may already be gone).
  // `corners`: a linear basis's values at every element corner (viz::SceneViewData::corners), drawn as they
  // are; empty for a constant basis.
  void setScene(const Mesh* mesh, const RgbField& B, const Camera& camera, bool resetCamera,
                const RgbField& corners = RgbField());
  // A new mesh: rebuilds the geometry. `resetCamera` places the camera at `camera`.
  void setMesh(const Mesh* mesh, const Camera& camera, bool resetCamera);
  // New colours for the same mesh (an iteration of the replay, a re-solve).
  void setRadiosity(const RgbField& B);
  // Colouring, exposure, tone map, gamma, smooth shading: the same options the figure exporters take.
  void setViewOptions(const viz::SceneViewOptions& options);
  // Colours the elements by one value each (e.g. a row of F) through the viz colour map, with its colour bar,
  // instead of by radiosity; an empty field returns to radiosity.
  void setScalarField(const Eigen::VectorXd& values, const std::string& title);
  // Steps without a solution show the materials instead, lit by a headlight so that the shapes read (a white
  // block in front of a white wall would otherwise vanish), as the exported material figures do. Takes effect
  // with the next setScene or setMesh (the caller always gives the step's mesh next: no repaint twice).
  void setMaterialView(bool materials);
  bool materialView() const { return materialView_; }
  const viz::SceneViewOptions& viewOptions() const { return options_; }
  const viz::SceneViewData& viewData() const { return data_; }
  const Mesh* mesh() const { return mesh_; }
  // The camera as the reader left it (for exporting the current view).
  Camera currentCamera() const;
  void setShowEdges(bool show);
  // The mesh edge lines while edges are shown (null otherwise).
  const viz::MeshEdgeLines* meshEdges() const;
  void setCaption(const QString& text);
  QString caption() const;
  bool showsColourBar() const;
  void setHighlighted(const std::vector<int>& elements);
  // Rays drawn in the scene (a raytrace step's ray tree); empty: none.
  void setRaySegments(const std::vector<viz::RaySegments>& segments);
  int raySegmentCount() const { return raySegments_; }
  const std::vector<int>& highlighted() const { return highlighted_; }
  // Copies the other view's camera (compare mode).
  void syncCameraFrom(const SceneView& other);
  void applyCamera(const Camera& camera);
  bool hasMesh() const { return mesh_ != nullptr; }
  // The element drawn at widget position `position`, or -1.
  int pickElement(QPoint position);
  // How often the view built its polydata (once per mesh) and rewrote only its colours (every iteration,
  // colouring or tone map since): the replay and the display keys must never rebuild the geometry.
  int geometryBuilds() const { return geometryBuilds_; }
  int colourUpdates() const { return colourUpdates_; }
  // The cells drawn (one per element).
  vtkPolyData* displayedPolyData() const;
  // The coarse stand-in drawn while the camera moves (null for a mesh below the threshold), and how long
  // its clustering took (once per mesh).
  vtkPolyData* standInPolyData() const;
  double standInBuildMilliseconds() const;
  // Whether the camera is moving now (the stand-in, when there is one, is what gets drawn).
  bool inMotion() const { return inMotion_; }
  // The camera moves without a drag (a walkthrough frame, a wheel step): the stand-in is drawn until the
  // camera has rested for kSettleMilliseconds.
  void noteCameraMotion();
  static constexpr int kSettleMilliseconds = 250;

 signals:
  void elementPicked(int element);

 protected:
  void resizeEvent(QResizeEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  // A drag begins or ends (the interactor style's Start/EndInteractionEvent).
  void onCameraInteraction(vtkObject* caller, unsigned long event, void* data);
  // The moving frames: the stand-in instead of the mesh, no FXAA; the still frame: the mesh, FXAA.
  void beginMotion();
  void endMotion();
  void rebuildHighlight();
  // The edge lines of mesh_ when they are shown; none otherwise.
  void rebuildEdges();
  // The caption's font shrinks (down to a floor) so that it fits a narrow pane, as in compare mode.
  void fitCaption();

  const Mesh* mesh_ = nullptr;
  viz::ScenePaint paint();
  // A new mesh: new cells, coloured. repaint3d() then only rewrites the colours of the same cells.
  void rebuildGeometry();
  void repaint3d();
  // The colour bar and the light outline that go with the colouring.
  void showColouring(const viz::ScenePaint& painted);
  void applyLighting();
  void fitViewAngle();
  viz::SceneViewData data_;
  viz::SceneViewOptions options_;
  vtkSmartPointer<vtkPolyData> polyData_;
  vtkSmartPointer<vtkPolyDataMapper> mapper_;
  vtkSmartPointer<vtkActor> actor_;
  std::unique_ptr<viz::SmoothInterpolation> smoothing_;  // of mesh_, once a smooth view asked for it
  std::unique_ptr<StandInActor> standIn_;                // of mesh_, when it is large
  bool inMotion_ = false;
  bool dragging_ = false;
  QTimer* settle_ = nullptr;               // the end of a motion without a drag
  vtkSmartPointer<vtkCellPicker> picker_;  // with a cell locator over polyData_, built at the first pick
  unsigned long styleObservers_[2] = {0, 0};
  int geometryBuilds_ = 0;
  int colourUpdates_ = 0;
  vtkSmartPointer<vtkActor> highlightActor_;
  vtkSmartPointer<vtkTextActor> caption_;
  bool materialView_ = false;
  vtkSmartPointer<vtkActor> emitterOutline_;      // material view: where the lights are
  vtkSmartPointer<vtkScalarBarActor> colourBar_;  // scalar colourings (a row of F, errors): values readable
  std::vector<int> highlighted_;
  bool showEdges_ = false;
  vtkSmartPointer<viz::MeshEdgeLines> edges_;  // while edges are shown
  std::vector<vtkSmartPointer<vtkActor>> rayActors_;
  int raySegments_ = 0;
};

}  // namespace rt::app
