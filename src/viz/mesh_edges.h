// The mesh edges of the 3D views, drawn as lines of their own: each element edge once, only where an element
// that owns it faces the camera. VTK's own edge drawing (vtkProperty::EdgeVisibility) shades every triangle
// by its distance to its projected edges, and a polygon that reaches behind the camera projects wrongly:
// whole faces came out in the edge colour whenever the camera stood inside a room. Lines are clipped like any
// other geometry. Polygons are one-sided (culled from behind), and the lines follow them: seen from outside a
// closed room, the edges of its far walls are not drawn through the near ones. Includes VTK: viz sources and
// the app.
#pragma once

#include <vtkCommand.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh.h"
#include "viz/vtk_geometry.h"

class vtkActor;
class vtkCamera;
class vtkCellArray;
class vtkPolyData;
class vtkRenderer;

namespace rt::viz {

// Every element edge once, as its pair of mesh vertices, and for corner k of element e (the edge from vertex
// k to vertex k + 1) its index: cornerEdge[firstCorner[e] + k].
struct MeshEdgeTable {
  std::vector<std::array<int, 2>> edges;  // lower vertex index first
  std::vector<int> firstCorner;           // n + 1 entries
  std::vector<int> cornerEdge;
};
MeshEdgeTable meshEdgeTable(const Mesh& mesh);

// The line actor of a mesh's edges and the renderer observer that keeps it following the camera: before
// every frame (the renderer's StartEvent) it finds the elements facing the camera, and only when that set
// changed does it rewrite the lines (an orbit inside a room rarely changes it). Owns copies of what it needs:
// the mesh may go away first.
class MeshEdgeLines : public vtkCommand {
 public:
  // `lineWidth` in pixels.
  static vtkSmartPointer<MeshEdgeLines> make(const Mesh& mesh, const Colour& colour, double lineWidth);
  // Adds the actor to `renderer` and follows its active camera; removeFrom() undoes both.
  void addTo(vtkRenderer& renderer);
  void removeFrom(vtkRenderer& renderer);
  vtkActor* actor() const;
  vtkPolyData* polyData() const;
  // Chooses the edges for `camera` now; returns whether the drawn set changed.
  bool follow(vtkCamera& camera);
  // The edges drawn, and how long the last choice took (ms).
  std::size_t shownEdges() const { return shown_; }
  double lastChoiceMilliseconds() const { return lastChoiceMilliseconds_; }

  void Execute(vtkObject* caller, unsigned long event, void* data) override;

 private:
  MeshEdgeLines() = default;
  void writeLines();

  MeshEdgeTable table_;
  std::vector<std::array<float, 4>> planes_;  // per element: normal and offset (n . x = d on the element)
  std::vector<std::uint8_t> facing_;          // per element, at the last choice
  std::vector<std::uint8_t> drawn_;           // per edge
  bool chosen_ = false;
  std::size_t shown_ = 0;
  double lastChoiceMilliseconds_ = 0;
  vtkSmartPointer<vtkPolyData> data_;
  vtkSmartPointer<vtkActor> actor_;
  unsigned long observer_ = 0;
};

}  // namespace rt::viz
