// Views of the meshes that follow the light (core/refine, docs/meshing.md):
//  - links: hierarchical radiosity's leaves coloured by their depth in the quadtree, and the links between
//    the nodes that exchange light drawn as lines between the nodes' centres, coloured by the deeper end's
//    level or by the link's form factor;
//  - discontinuity: the refined mesh (radiosity, element edges) with the critical segments over it, umbra and
//    outer penumbra boundaries (extremal lines) apart from the lines inside the penumbra;
//  - t-vertices: the refined mesh with its hanging vertices and the long edges they split.
// The refined mesh alone is the scene view of the solution with edges (writeSceneFigure). Public header: no
// VTK.
#pragma once

#include <string>
#include <vector>

#include "core/refine/refine.h"
#include "core/scene.h"
#include "viz/colour_map.h"
#include "viz/figure_output.h"
#include "viz/scene_view.h"

namespace rt::viz {

enum class LinkColouring { Level, FormFactor };
// "level", "formfactor"; throws std::invalid_argument.
LinkColouring linkColouringFromName(const std::string& name);

struct LinksViewOptions {
  FigureSize size{1200, 900, 96.0};
  LinkColouring colouring = LinkColouring::Level;
  ColourMap map = ColourMap::Viridis;
  // Only the links through which this leaf element gathers (its own and its ancestors'); -1: every link.
  int element = -1;
  std::string caption;  // empty: chosen
};

// The links whose receiving node contains the centroid of leaf `element` (the node lies in the element's
// plane and the centroid is inside it): the light that element gathers, at every level above it.
std::vector<int> linksGatheredBy(const RefinedSolution& solution, int element);

// Throws std::invalid_argument when the solution has no links (not hierarchical) or the element is not in
// the mesh, std::runtime_error when the file cannot be written.
void writeLinksFigure(const RefinedSolution& solution, const Camera& camera, const LinksViewOptions& options,
                      const std::string& path);

struct DiscontinuityViewOptions {
  FigureSize size{1200, 900, 96.0};
  ImageOptions image;   // display pipeline of the radiosity under the lines (size taken from `size`)
  std::string caption;  // empty: chosen
};

// Counts of the two kinds of critical segments the view draws.
struct CriticalLineCounts {
  std::size_t extremal = 0, interior = 0;
};
CriticalLineCounts countCriticalLines(const RefinedSolution& solution);

// Throws std::invalid_argument when the solution has no radiosity for its mesh, std::runtime_error when the
// file cannot be written. A solution without critical segments is drawn with a caption saying so.
void writeDiscontinuityFigure(const RefinedSolution& solution, const Camera& camera,
                              const DiscontinuityViewOptions& options, const std::string& path);

// The refined mesh with its T-vertices as dots and the long edges they split drawn over it (the radiosity as
// `options.image` sets it, smooth or flat). Returns the caption drawn on it. Throws as the one above.
std::string writeTVertexFigure(const RefinedSolution& solution, const Camera& camera,
                               const DiscontinuityViewOptions& options, const std::string& path);

}  // namespace rt::viz
