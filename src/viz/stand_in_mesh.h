// A coarse stand-in of a large element mesh, drawn instead of it while the camera moves. A software
// renderer's frame time follows the triangles it draws, not the pixels: the million-element museum takes some
// 120 ms a frame, the stand-in's hundred thousand or so triangles a fraction of that. On the still frame
// after the motion the full mesh is drawn again, so what the reader reads, picks and exports is never the
// stand-in.
//
// The stand-in is vertex clustering in the way of vtkQuadricClustering (Lindstrom's out-of-core clustering):
// the corners are binned on a uniform grid, each bin's representative point minimises the squared distances
// to the planes of the elements around it (so corners and edges of the room stay where they are), and the
// triangles whose three corners fall in three different bins are kept. Two things VTK's filter does not do
// are needed here, which is why it is not used: the stand-in must carry the colours (the filter passes no
// point data and at most one input cell's data per output triangle), and it must follow every recolouring
// (an iteration, a tone map) without being rebuilt. So each bin is split by the facing of its elements (six
// classes, by the dominant axis of the normal): the two faces of a thin partition, or a floor and the wall
// standing on it, never share a colour, and back-face culling still hides the far side of a wall. Each
// corner remembers its cluster, and a recolouring averages the corners' colours per cluster (one pass over
// the corners, milliseconds at a million elements).
#pragma once

#include <vtkSmartPointer.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "viz/scene_view.h"

class vtkPolyData;

namespace rt::viz {

// Meshes of more triangles than this get a stand-in. Below it a frame of the full mesh already takes less
// than about 35 ms on the software renderer (the 50k-element museum, 100k triangles: 25 ms with the window),
// and a small scene must look and behave exactly as it always did.
constexpr std::size_t kStandInAboveTriangles = 200'000;
// The stand-in's size: about 26 ms a frame in the app under llvmpipe (docs/benchmarks.md), whatever the
// mesh's size.
constexpr std::size_t kStandInTargetTriangles = 120'000;

// The triangles a renderer draws for the mesh (an n-gon element is n - 2 of them).
std::size_t triangleCount(const Mesh& mesh);
bool wantsStandIn(const Mesh& mesh);

class StandInMesh {
 public:
  // Clusters `mesh` to roughly `targetTriangles` triangles. Keeps no reference to the mesh.
  explicit StandInMesh(const Mesh& mesh, std::size_t targetTriangles = kStandInTargetTriangles);

  // Triangles with one point per cluster, point data "colour" (RGB, unsigned char) painted from `paint`.
  vtkSmartPointer<vtkPolyData> makePolyData(const ScenePaint& paint) const;
  // Rewrites the "colour" array of `data` (from makePolyData) with the clusters' mean colours of `paint`'s
  // corners (grey without paint) and marks it modified. Throws std::invalid_argument when the paint's
  // corners are not the mesh's.
  void recolour(vtkPolyData& data, const ScenePaint& paint) const;

  std::size_t clusterCount() const { return clusterCorners_.size(); }
  std::size_t triangleCount() const { return triangles_.size() / 3; }
  std::size_t cornerCount() const { return clusterOfCorner_.size(); }
  double binSize() const { return binSize_; }

 private:
  void build(const Mesh& mesh, double binSize);

  double binSize_ = 0.0;
  std::vector<std::int32_t> clusterOfCorner_;  // corner k of element e in the paint's order -> cluster
  std::vector<std::int32_t> clusterCorners_;   // corners per cluster (the divisor of the mean colour)
  std::vector<float> positions_;               // 3 per cluster
  std::vector<std::int32_t> triangles_;        // 3 cluster ids each, counter-clockwise as the elements
};

}  // namespace rt::viz
