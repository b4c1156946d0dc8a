// The 3D view of a solved scene: elements coloured by radiosity, optional mesh edges, highlighted elements,
// and picking (a click names the element under the cursor). Two of them side by side make the compare mode;
// they share a camera through syncCameraFrom().
#pragma once

#include <vector>

#include "app/vtk_widget.h"
#include "core/scene.h"
#include "viz/scene_view.h"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkScalarBarActor;
class vtkTextActor;

namespace rt::app {

class SceneView : public VtkWidget {
  Q_OBJECT
 public:
  explicit SceneView(QWidget* parent = nullptr);
  ~SceneView() override;

  // A new mesh and its radiosity at once (the previous mesh may already be gone).
  void setScene(const Mesh* mesh, const RgbField& B, const Camera& camera, bool resetCamera);
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
  void setCaption(const QString& text);
  QString caption() const;
  bool showsColourBar() const;
  void setHighlighted(const std::vector<int>& elements);
  const std::vector<int>& highlighted() const { return highlighted_; }
  // Copies the other view's camera (compare mode).
  void syncCameraFrom(const SceneView& other);
  void applyCamera(const Camera& camera);
  bool hasMesh() const { return mesh_ != nullptr; }
  // The element drawn at widget position `position`, or -1.
  int pickElement(QPoint position);

 signals:
  void elementPicked(int element);

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  void rebuildHighlight();
  // The caption's font shrinks (down to a floor) so that it fits a narrow pane, as in compare mode.
  void fitCaption();

  const Mesh* mesh_ = nullptr;
  void repaint3d();
  void applyLighting();
  void fitViewAngle();
  viz::SceneViewData data_;
  viz::SceneViewOptions options_;
  vtkSmartPointer<vtkPolyData> polyData_;
  vtkSmartPointer<vtkPolyDataMapper> mapper_;
  vtkSmartPointer<vtkActor> actor_;
  vtkSmartPointer<vtkActor> highlightActor_;
  vtkSmartPointer<vtkTextActor> caption_;
  bool materialView_ = false;
  vtkSmartPointer<vtkActor> emitterOutline_;      // material view: where the lights are
  vtkSmartPointer<vtkScalarBarActor> colourBar_;  // scalar colourings (a row of F, errors): values readable
  std::vector<int> highlighted_;
  bool showEdges_ = false;
};

}  // namespace rt::app
