// Sample rays between two elements: unoccluded segments in one colour, occluded ones stopping at the first
// element they hit in another, over the scene drawn faintly. The sampling and the ray tests are core's
// (stratified points on the elements, Embree visibility), so the fraction shown is what the ray-cast form
// factors use. Public header: no VTK.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/formfactor/local_lines.h"
#include "core/mesh.h"
#include "core/scene.h"
#include "viz/figure_output.h"

namespace rt::viz {

struct SampledRay {
  Vec3 from, to;  // on element i and on element j
  bool visible = false;
  int occluder = -1;  // first element hit when not visible
  Vec3 hit;           // where it was hit (== to when visible)
};

struct RaySample {
  int from = -1, to = -1;
  std::vector<SampledRay> rays;
  double visibleFraction() const;
};

// `count` stratified point pairs, deterministic for the seed. Throws std::invalid_argument for bad element
// indices.
RaySample sampleRays(const Mesh& mesh, int from, int to, int count, std::uint64_t seed = 1);

struct RaysViewOptions {
  FigureSize size{1200, 900, 96.0};
  std::string caption;  // empty: "rays from i to j: k of n unoccluded"
};

// Local lines leaving element `from` (core/formfactor/local_lines.h), the ones landing first on `target`
// in one colour, those landing elsewhere in another, the escaped ones faint and cut at a tenth of the scene.
// `total` is the number of lines the estimate counted (the figure may draw fewer, the first ones).
void writeLocalLinesFigure(const Mesh& mesh, const Camera& camera, int from, int target,
                           const std::vector<LocalLine>& lines, long total, const RaysViewOptions& options,
                           const std::string& path);

// PNG; PDF/SVG embed the rendered image.
void writeRaysFigure(const Mesh& mesh, const Camera& camera, const RaySample& sample,
                     const RaysViewOptions& options, const std::string& path);

}  // namespace rt::viz
