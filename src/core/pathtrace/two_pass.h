// The two-pass method: a radiosity solution shown or queried through a second pass at each point. The
// emitters' direct light is computed exactly at the point itself: Lambert's point-to-polygon form factor,
// less, where the shaft test finds something that may block, the form factor of the part of the emitter that
// the blockers' polygons hide from the point (cut out by the cones from the point over them, in double
// precision; shadow rays only for a point on no known surface), and everything else arrives by one final
// gather from the solution: cosine-distributed rays that take, at the element they hit, its solved radiosity
// minus its emission. The mesh's errors then only enter through the indirect light, averaged over the
// hemisphere; shadows and the light's falloff are exact.
//
// Given the solution's form factors, the gather goes one step further: what the hit element reflects is split
// into the direct light it receives, which the solution only knows as an average over the element, and the
// rest. The direct part is then taken at the hit point itself (Lambert's formula, less a shadow ray's
// estimate of the hidden part where something may block), so that a shadow or the light's falloff across a
// coarse element does not smear into the gathered light. A gather hit close to the point (within a few
// element sizes; every hit by default) sees its element's flat indirect light at a large solid angle, so it
// gathers that part anew, one bounce further on, with the direct light again taken where those rays land
// (docs/pathtrace.md).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "core/formfactor/formfactor_matrix.h"
#include "core/formfactor/ray_scene.h"
#include "core/formfactor/sampling.h"
#include "core/formfactor/shaft_culling.h"
#include "core/io/rgb_image.h"
#include "core/pathtrace/estimate.h"
#include "core/pathtrace/tracing_scene.h"

namespace rt {

struct TwoPassOptions {
  int gatherRays = 4096;  // final-gather rays per point
  int shadowRays = 256;   // per point and emitter, only where something may block
  int batches = 16;       // independent batches (standard errors from their spread)
  // Gather hits closer than this many element sizes gather their indirect light anew, one bounce further on,
  // with nearRays rays. At every hit by default: the solution's flat element averages then enter one bounce
  // later, where the mesh's error is spread over the hit point's hemisphere, and the answer is unbiased with
  // respect to the mesh to well within its noise (the closed Cornell box's floor: 95 % of the values within
  // 3 sigma of the long path-traced reference, against 83 % when only hits within 2 element sizes do so).
  // Three rays: most of the noise left is the secondary gather's (the direct light at its hit points varies
  // most), and three balances it against the gather's own at the least cost (docs/benchmarks.md).
  double nearFactor = std::numeric_limits<double>::infinity();
  int nearRays = 3;
  // The picture: pixels on a silhouette or on the border of two patches (where a neighbour shows another
  // patch or nothing) average this many jittered samples over the pixel, as the path tracer and the radiosity
  // picture do, instead of taking the surface at the pixel's centre alone; 1 samples only the centre.
  int edgeSamples = 16;
  std::uint64_t seed = 1;
};

class TwoPass {
 public:
  // `B` is the solution on `solution` (n x 3), `F` its form factors (null: gather B - E as it is); all of
  // them and the tracing scene must outlive this.
  TwoPass(const TracingScene& tracing, const Mesh& solution, const RgbField& B,
          const FormFactorMatrix* F = nullptr);
  TwoPass(const TwoPass&) = delete;
  TwoPass& operator=(const TwoPass&) = delete;

  // H, B and their standard errors (the Monte Carlo part: shadow rays and the gather; the solution's own
  // discretisation error is not in them). TBB parallel, deterministic for a seed.
  std::vector<PointEstimate> estimate(const std::vector<SurfacePoint>& points,
                                      const TwoPassOptions& options) const;
  // The same for points whose elements of the tracing scene are known (-1: none).
  std::vector<PointEstimate> estimate(const std::vector<SurfacePoint>& points,
                                      const std::vector<int>& elements, const TwoPassOptions& options) const;

  // The two-pass picture (two_pass_image.cpp): per pixel, the point the pixel's centre ray reaches first, and
  // B there, E + rho H. The direct part of H is exact at every pixel; the gathered part, which varies slowly
  // along a surface, is gathered (options.gatherRays rays) at every gatherSpacing-th pixel of each row and
  // column, more densely where other surfaces are near (renderGatherRefinement), and interpolated between
  // those of the same patch. Back sides and nothing are black.
  RgbImage render(const Camera& camera, int width, int height, const TwoPassOptions& options,
                  int gatherSpacing = 1) const;

  // The emitters' direct irradiance alone, with its standard error (zero where no ray was needed).
  Rgb direct(const SurfacePoint& point, int element, const TwoPassOptions& options, std::uint64_t index,
             Rgb& error) const;

 private:
  // Pixels whose neighbours show another patch or nothing (`patch`: each pixel centre's patch, -1 for none)
  // get the mean of options.edgeSamples jittered samples over the pixel (render()).
  void antialiasEdges(const Camera& camera, int width, int height, const TwoPassOptions& options,
                      const std::vector<int>& patch, const std::vector<Rgb>& indirectAt,
                      RgbImage& image) const;

  // The gathered (indirect) irradiance and its standard error; `bounce` (when given) receives the part of it
  // that is the direct light taken at the gather's hits, and its standard error; `harmonicDistance` (when
  // given) the harmonic mean of the distances the gather's rays travel (a miss counts as infinitely far):
  // the scale over which the gathered light may change along the surface (Ward, Rubinstein and Clear 1988).
  Rgb gather(const SurfacePoint& point, int element, const TwoPassOptions& options, std::uint64_t index,
             Rgb& error, Rgb* bounce = nullptr, Rgb* bounceError = nullptr,
             double* harmonicDistance = nullptr) const;
  // The indirect irradiance at a point of solution element `element`: cosine rays from the batch's padded
  // strata (those of path `path`) taking, where they hit, the direct light at the hit point and the element's
  // indirect light (B - E without form factors).
  Rgb secondaryGather(const Vec3& point, const Vec3& normal, int element, int rays,
                      const PaddedStrata& strata, int path, PairRandom& random) const;
  // F(dA at the point -> the part of emitter element `emitter` that the patches in `blockers` hide), exactly:
  // the emitter is cut by the cones from the point over each blocker's polygons (ShadowClipper).
  double hiddenExactly(const Vec3& point, const Vec3& normal, int emitter,
                       const std::vector<int>& blockers) const;
  // One-sample unbiased estimate of the emitters' direct irradiance at a point of tracing element `element`:
  // Lambert's formula, less a shadow ray to the emitters' point `light` (in [0,1]^2) where something may
  // block.
  Rgb directSample(const Vec3& point, const Vec3& normal, int element, const Vec2& light) const;

  const TracingScene& tracing_;
  const Mesh& solution_;
  const RgbField& B_;
  ShaftCulling shaft_;
  std::unique_ptr<RayScene> solutionRays_;
  std::vector<int> patchElement_;                    // per patch: one element of the solution's mesh on it
  std::vector<std::vector<Polygon>> patchPolygons_;  // per patch: the polygons of its tracing elements
  // With form factors: per solution element, the irradiance that is not the emitters' direct light,
  // (B - E) / rho - sum_l F_il E_l, per channel (0 where rho is 0).
  RgbField indirect_;
  std::vector<double> receiving_;  // per solution element: the part that receives light at all
};

}  // namespace rt
