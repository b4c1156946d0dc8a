#include "core/raytrace/ray_cost.h"

#include <algorithm>

namespace rt {

RayCost whittedRayCost(const RayCostInputs& in) {
  const double pixels = static_cast<double>(std::max<std::int64_t>(in.pixels, 0));
  const double samples = std::max(in.pixelSamples, 1), lights = std::max(in.lights, 0),
               shadow = std::max(in.shadowRays, 0), branching = std::max(in.branching, 1);
  RayCost c;
  // Generation k of the tree holds b^k rays, each of which reaches a surface and is a node.
  double generation = 1;
  for (int k = 0; k <= std::max(in.depth, 0); ++k, generation *= branching) c.treeNodes += generation;
  c.perPrimaryRay = c.treeNodes * (1 + lights * shadow);
  c.perPixel = samples * c.perPrimaryRay;
  c.total = pixels * c.perPixel;
  c.primary = pixels * samples;
  c.secondary = c.primary * (c.treeNodes - 1);
  c.shadow = c.primary * c.treeNodes * lights * shadow;
  return c;
}

}  // namespace rt
