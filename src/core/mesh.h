// The computational mesh: elements obtained by subdividing patches. Elements are what form factors and
// solvers work on. Every element remembers its parent patch; vertices are shared between elements of the same
// patch (and merged across patches where they coincide) so that per-vertex radiosity can be interpolated for
// display.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/scene.h"

namespace rt {

struct Element {
  // Indices into Mesh::vertices, counter-clockwise seen from the front: 3 or 4 of them, or up to 8 when a
  // convex patch is kept as one element (MeshOptions::Mode::None).
  std::vector<int> vertices;
  int patch = -1;  // parent patch in the scene
  Vec3 normal;
  Vec3 centroid;
  double area = 0.0;
};

struct MeshOptions {
  enum class Mode { None, Count, MaxEdge };
  Mode mode = Mode::None;  // None: one element per patch, in file order (convex n-gons kept whole up to 8)
  int count = 1;           // Count: each patch is split N x N (quads) or into N^2 triangles (triangles)
  double maxEdge = 0.0;    // MaxEdge: split until no element edge is longer than this
  // Count and MaxEdge: first cut each patch along the lines where other surfaces stand on it
  // (contact_lines.h), so that no element straddles a block's footprint. The mesh chosen for a scene given
  // without mesh options does; explicit options keep the plain grid unless asked.
  bool splitAtContacts = false;
  // With splitAtContacts: also cut each patch along the outline of any patch parallel to it that lies in
  // front of it within this gap, as a fraction of the scene's diagonal (contact_lines.h); 0: no such cut. The
  // default mesh's elements are about a tenth of the diagonal (82 mm on the 0.96 m Cornell box), and a patch
  // closer than a fifth of that (2 % of the diagonal: 19 mm there, 17 cm in a 5 m room) casts an edge of
  // shadow sharper than an element onto the one behind: the lights hung 0.1 mm (Radiance models) and 1 cm
  // (McGuire's CornellBox-Original) below an uncut ceiling, a picture on a wall, a rug on a floor. A patch
  // farther away shades the one behind smoothly, and the elements resolve that without a cut.
  double overlapGap = 0.02;
};

// Where the mesh of `options` cuts the scene's patches: per cut patch and per surface cutting it, the number
// of segments, whether they are contacts or overlaps, and for overlaps the largest gap (scene units).
struct MeshCut {
  int patch = -1;
  int surface = -1;  // the cutting surface
  bool overlap = false;
  double gap = 0;
  int segments = 0;
};
std::vector<MeshCut> meshCuts(const Scene& scene, const MeshOptions& options);
// One line per cut, naming the surfaces: "ceiling (patch 3) along the outline of light, 0.1 mm in front".
std::vector<std::string> describeMeshCuts(const Scene& scene, const std::vector<MeshCut>& cuts);

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<Element> elements;
  // For each vertex, the elements that use it (for interpolation and adjacency).
  std::vector<std::vector<int>> vertexElements;
  // Per-element material data copied from the scene, so that solvers only need the mesh.
  RgbField reflectance;  // n x 3
  RgbField emission;     // n x 3

  std::size_t size() const { return elements.size(); }
  Polygon polygon(int element) const;
  Eigen::VectorXd areas() const;
  // Indices of elements sharing an edge with element e.
  std::vector<int> edgeNeighbours(int element) const;
  // Hash of the geometry only (vertices, elements): form factors can be cached under it, because changing
  // reflectance or emission does not change F.
  std::uint64_t geometryHash() const;
};

// Builds the mesh of a scene. Throws InputError for impossible options (count < 1, maxEdge <= 0) and, before
// allocating anything, for a mesh that would not fit in memory (the message gives the element count, the
// memory it needs and a coarser setting).
Mesh buildMesh(const Scene& scene, const MeshOptions& options = {});

// How many elements buildMesh would make, without making them.
double estimatedElementCount(const Scene& scene, const MeshOptions& options);
// A mesh for a scene given without mesh options: the largest --max-edge (to 2 significant digits) that gives
// at least `elements` elements, or one element per patch when the scene has that many patches already. One
// element per polygon is rarely right (the JSON Cornell box: 20 elements, 55 % error on the floor). The mesh
// is cut along contact lines.
MeshOptions defaultMeshOptions(const Scene& scene, double elements = 800);
// Copies reflectance/emission from the scene into an existing mesh (after a material-only change).
void refreshMaterials(Mesh& mesh, const Scene& scene);

}  // namespace rt
