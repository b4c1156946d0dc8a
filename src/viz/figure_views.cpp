// The figure driver's views about one element: the Nusselt analog, the hemicube, rays, exact visibility, and
// the meshes that follow the light (links, discontinuities).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/formfactor/analytic.h"
#include "core/formfactor/hemicube.h"
#include "viz/colour_map.h"
#include "viz/exact_visibility.h"
#include "viz/figure_driver_support.h"
#include "viz/figure_output.h"
#include "viz/hemicube_view.h"
#include "viz/meshing_view.h"
#include "viz/nusselt_view.h"
#include "viz/rays_view.h"
#include "viz/visibility_view.h"

namespace rt::viz::detail {

void nusseltFigure(const Computed& c, const FigureRequest& a) {
  const int j = a.target >= 0 ? a.target : firstEmitter(c.mesh);
  const int i = a.element >= 0 ? a.element : bestViewer(c.mesh, j);
  const Element& from = c.mesh.elements[i];
  const NusseltConstruction construction =
      nusseltConstruction(from.centroid, from.normal, c.mesh.polygon(j), 96);
  NusseltViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.title = "Nusselt analog: centre of element " + std::to_string(i) + " to element " + std::to_string(j);
  say(a, "nusselt: projected area / pi = ", construction.diskAreaFraction, ", exact = ", construction.exact);
  std::string part = a.part;
  if (part == "auto") part = figureFormatOf(a.output) == FigureFormat::Png ? "hemisphere" : "disk";
  if (part == "disk")
    writeNusseltDiskFigure(construction, o, a.output);
  else if (part == "hemisphere" || part == "3d")
    writeNusseltHemisphereFigure(construction, o, a.output);
  else
    throw std::invalid_argument("--part for the nusselt view is disk or hemisphere, not '" + part + "'");
}

void hemicubeFigure(const Computed& c, const FigureRequest& a) {
  const int i = a.element >= 0 ? a.element : bestViewer(c.mesh, firstEmitter(c.mesh));
  // A teaching resolution by default: pixels large enough to see.
  const int resolution = a.resolutionGiven ? a.resolution : 16;
  const HemicubeFaces faces = renderHemicube(c.mesh, i, resolution);
  HemicubeViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.colouring = a.colour == "delta" ? HemicubeColouring::DeltaFormFactors : HemicubeColouring::ItemBuffer;
  if (a.colour != "delta" && a.colour != "items" && a.colourGiven)
    throw std::invalid_argument("--colour for the hemicube view is items or delta, not '" + a.colour + "'");
  o.map = colourMapFromName(a.colourMap);
  if (a.part == "3d" || a.part == "hemisphere")
    writeHemicube3dFigure(c.mesh, faces, o, a.output);
  else if (a.part == "auto" || a.part == "faces")
    writeHemicubeFacesFigure(faces, c.mesh.size(), o, a.output);
  else
    throw std::invalid_argument("--part for the hemicube view is faces or 3d, not '" + a.part + "'");
}

void raysFigure(const Computed& c, const FigureRequest& a) {
  const int j = a.target >= 0 ? a.target : firstEmitter(c.mesh);
  int i = a.element;
  if (i < 0) {
    // The default shows occlusion when there is some: among the elements that face j, the one whose view of j
    // is closest to half blocked (a quick 16-ray estimate on the 64 best-placed candidates).
    std::vector<std::pair<double, int>> candidates;
    const Polygon target = c.mesh.polygon(j);
    for (std::size_t e = 0; e < c.mesh.size(); ++e)
      if (static_cast<int>(e) != j)
        if (const double f =
                pointToPolygonFormFactor(c.mesh.elements[e].centroid, c.mesh.elements[e].normal, target);
            f > 0)
          candidates.emplace_back(f, static_cast<int>(e));
    std::sort(candidates.rbegin(), candidates.rend());
    if (candidates.size() > 64) candidates.resize(64);
    double best = 2;
    i = candidates.empty() ? (j == 0 ? 1 : 0) : candidates.front().second;
    for (const auto& [f, e] : candidates) {
      const double blocked = std::abs(sampleRays(c.mesh, e, j, 16).visibleFraction() - 0.5);
      if (blocked < best) {
        best = blocked;
        i = e;
      }
    }
  }
  const int samples = a.samplesGiven ? a.samples : 64;
  const RaySample sample = sampleRays(c.mesh, i, j, samples);
  say(a, "rays: ", sample.visibleFraction() * 100, "% of ", samples, " unoccluded from ", i, " to ", j);
  RaysViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  writeRaysFigure(c.mesh, c.scene.cameraOrDefault(), sample, o, a.output);
}

void visibilityFigure(const Computed& c, const FigureRequest& a) {
  // Default: the element that sees the emitter closest to half blocked is the telling one.
  const int j = a.target >= 0 ? a.target : firstEmitter(c.mesh);
  const int i = a.element >= 0 ? a.element : halfBlockedViewer(c.mesh, j, bestViewer(c.mesh, j));
  const VisibilityRegions regions = exactVisibilityRegions(c.mesh, i, j);
  VisibilityViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  say(a, "visibility: F = ", regions.formFactor, " of ", regions.unoccludedFormFactor, " unoccluded");
  writeVisibilityFigure(regions, o, a.output);
}

void linksFigure(const Computed& c, const FigureRequest& a) {
  const RefinedSolution s = refined(c, a, RefineMode::Hierarchical);
  LinksViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.colouring = linkColouringFromName(a.linkColour);
  o.map = colourMapFromName(a.colourMap);
  if (a.element >= static_cast<int>(s.mesh.size()))
    throw std::invalid_argument("--element " + std::to_string(a.element) + " is outside the " +
                                std::to_string(s.mesh.size()) + " leaves of the hierarchy");
  o.element = a.element;
  writeLinksFigure(s, c.scene.cameraOrDefault(), o, a.output);
}

void discontinuityFigure(const Computed& c, const FigureRequest& a) {
  const RefinedSolution s = refined(c, a, RefineMode::Discontinuity);
  DiscontinuityViewOptions o;
  o.size = {a.width, a.height, a.dpi};
  o.image = sceneOptions(a).image;
  const CriticalLineCounts counts = countCriticalLines(s);
  say(a, "discontinuity: ", counts.extremal, " umbra/penumbra boundaries, ", counts.interior,
      " lines inside penumbrae");
  writeDiscontinuityFigure(s, c.scene.cameraOrDefault(), o, a.output);
}

// Run time against error from a table measured earlier (bench formfactors or bench solvers CSV).
}  // namespace rt::viz::detail
