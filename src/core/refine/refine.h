// Meshes that follow the light: one entry point for the three refining solvers of the course.
//  - adaptive:       solve on a coarse mesh, split elements whose radiosity differs too much from a
//  neighbour's,
//                    recompute only the new rows and columns of F, solve again (Cohen & Wallace ch. 8).
//  - discontinuity:  compute the umbra/penumbra boundaries cast by area lights past polygonal occluders (EV
//  and VE
//                    critical surfaces) and mesh the receivers with those lines as constraints (Heckbert
//                    1992, Lischinski, Tampieri & Greenberg 1992).
//  - hierarchical:   element quadtrees per patch, links between nodes at the level the error oracle allows,
//  gather
//                    over links and push-pull (Hanrahan, Salzman & Aupperle 1991).
//  - uniform:        the plain mesh (max edge) with the same form factors and solver, as the reference they
//  beat.
// All produce an rt::Mesh with one radiosity per element, so the viewer and image export show them like any
// solution.
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"
#include "core/refine/discontinuity.h"

namespace rt {

enum class RefineMode { Uniform, Adaptive, Discontinuity, Hierarchical };
std::string toString(RefineMode mode);
RefineMode refineModeFromString(const std::string& name);  // "uniform", "adaptive", ...; throws InputError

struct RefineOptions {
  RefineMode mode = RefineMode::Adaptive;
  // The starting mesh (adaptive, discontinuity, uniform): no element edge longer than this, in scene units.
  // 0 picks a fifth of the scene's bounding-box diagonal (the Cornell box then starts from ~140 elements).
  double initialMaxEdge = 0;
  // Smallest element edge any refinement may produce; 0 = initial edge / 16.
  double minEdge = 0;
  int visibilitySamples = 16;  // rays per receiver point and element pair (or link)

  // Adaptive: split an element when its radiosity (luminance) differs from an edge/vertex neighbour's on the
  // same surface by more than gradientTolerance x the area-weighted mean radiosity of the reflecting
  // elements.
  double gradientTolerance = 0.3;
  int maxPasses = 4;  // solves; a split happens between two of them
  int maxElements = 2000;

  // Discontinuity: largest triangle edge of the constrained mesh (0 = initialMaxEdge). Critical lines shorter
  // than minEdge are dropped.
  double discontinuityMaxEdge = 0;

  // Hierarchical: link two nodes when their estimated transfer is below linkTolerance, measured as F (oracle
  // "F") or as F x B-luminance / the brightest emitter's luminance (oracle "BF"). minArea (0 = minEdge^2)
  // stops the quadtrees.
  double linkTolerance = 0.02;
  bool brightnessWeighted = true;  // the BF oracle
  double minArea = 0;
  int refinementRounds = 3;  // BF: solve, re-refine the links with the new radiosities, repeat

  double solverTolerance = 1e-6;  // Gauss-Seidel: relative residual; hierarchical: relative change of B
  int maxSweeps = 500;
};

// A hanging vertex: `vertex` lies on the edge edgeStart-edgeEnd of element `element` without being one of its
// vertices. Per-vertex interpolation must set its value to (1-t) value(edgeStart) + t value(edgeEnd).
struct TVertex {
  int vertex = -1;
  int element = -1;
  int edgeStart = -1, edgeEnd = -1;
  double t = 0;
};

// A hierarchical link: `to` gathers from `from` with form factor F (both are quadtree nodes; level 0 =
// patch).
struct HierarchyLink {
  Polygon from, to;
  int fromLevel = 0, toLevel = 0;
  double formFactor = 0;
};

struct RefinePass {
  std::size_t elements = 0;
  std::size_t pairsComputed =
      0;                  // form-factor pairs (i, j) evaluated in this pass (both directions count once)
  std::size_t split = 0;  // elements split after this pass
  int sweeps = 0;
  double seconds = 0;
};

struct RefineStats {
  RefineMode mode = RefineMode::Adaptive;
  std::size_t initialElements = 0;
  std::size_t elements = 0;
  std::size_t pairsComputed =
      0;                  // adaptive/uniform/discontinuity: F pairs evaluated; hierarchical: links tried
  std::size_t links = 0;  // hierarchical: links in the final hierarchy
  std::size_t hierarchyNodes = 0;  // hierarchical: quadtree nodes
  int maxLevel = 0;
  std::size_t tVertices = 0;
  std::size_t criticalSegments = 0;  // discontinuity
  std::size_t raysCast = 0;
  double formFactorSeconds = 0, solveSeconds = 0, seconds = 0;
  std::vector<RefinePass> passes;
  std::string notes;            // e.g. which constrained triangulator meshed the receivers
  std::string summary() const;  // one line
};

struct RefinedSolution {
  Mesh mesh;                       // the final elements (leaves)
  RgbField B;                      // one radiosity per element (W/m^2)
  std::vector<int> elementLevel;   // subdivision depth of each element (0 = starting mesh / patch)
  std::vector<TVertex> tVertices;  // hanging vertices of the final mesh
  std::vector<CriticalSegment> discontinuities;  // discontinuity mode: the constraint lines on the receivers
  std::vector<HierarchyLink> links;              // hierarchical mode: every link of the final hierarchy
  RefineStats stats;
};

// Runs the requested refinement. Throws InputError for impossible options, Cancelled when progress asks.
RefinedSolution solveRefined(const Scene& scene, const RefineOptions& options,
                             Progress& progress = noProgress());

// The starting edge length solveRefined uses when initialMaxEdge is 0.
double defaultInitialMaxEdge(const Scene& scene);

// A crack-free version for Gouraud display: every element with hanging vertices on its edges becomes a fan of
// triangles around its centroid through those vertices. sourceElement[k] is the element display element k
// came from (display radiosity = B.row(sourceElement[k])).
Mesh conformingDisplayMesh(const RefinedSolution& solution, std::vector<int>* sourceElement = nullptr);

// Per-vertex radiosity for display: area-weighted average of the elements around each vertex (same patch only
// would be better at creases; the viewer decides), with hanging vertices constrained to their edge's
// interpolation.
RgbField vertexRadiosity(const RefinedSolution& solution);

// Radiosity of the solution at a point of a patch (the element of that patch containing it; nearest centroid
// when the point is on no element). Used to compare solutions on different meshes.
Rgb radiosityAt(const RefinedSolution& solution, int patch, const Vec3& point);

// Radiosity at a point as smooth shading shows it: vertex values (area-weighted averages of the elements of
// the same patch around each vertex) interpolated linearly over the element's fan triangles.
Rgb interpolatedRadiosityAt(const RefinedSolution& solution, int patch, const Vec3& point);

// Area-weighted RMS difference of luminance between `solution` and `reference`, sampled at the reference's
// element centroids, divided by the reference's area-weighted mean luminance over reflecting elements.
// `interpolated` compares the smooth-shaded solution (interpolatedRadiosityAt) instead of the element values.
double relativeRmsError(const RefinedSolution& solution, const RefinedSolution& reference,
                        bool interpolated = false);

double luminance(const Eigen::Ref<const Eigen::RowVector3d>& rgb);

// The area-weighted mean luminance of B over the elements that emit nothing (over all of them when every one
// emits): the scale of adaptive subdivision's split threshold, tolerance x this.
double meanReflectingLuminance(const Mesh& mesh, const RgbField& B);

}  // namespace rt
