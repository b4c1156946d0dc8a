// The cost of recursive ray tracing, counted before tracing: every pixel sends its primary rays, every
// surface a ray reaches sends one shadow ray per light sample to each light, and every hit above the depth
// limit spawns its secondary rays (one for a mirror, two with refraction too). The Whitted tracer's counts
// match it exactly when every ray finds a surface and every surface reflects (a closed room of mirrors); in
// any other scene it is the bound the counts stay under.
#pragma once

#include <cstdint>

namespace rt {

struct RayCostInputs {
  std::int64_t pixels = 1;
  int pixelSamples = 1;  // primary rays per pixel (supersampling)
  int lights = 1;
  int shadowRays = 1;  // per light per hit
  int depth = 0;       // recursion depth: secondary generations after the primary ray
  int branching = 1;   // secondary rays per hit: 1 mirror, 2 mirror and refraction
};

struct RayCost {
  double treeNodes = 0;      // rays that reach a surface in one full ray tree: 1 + b + ... + b^depth
  double perPrimaryRay = 0;  // treeNodes (1 + lights shadowRays)
  double perPixel = 0;       // pixelSamples perPrimaryRay
  double total = 0;          // pixels perPixel
  double primary = 0, secondary = 0, shadow = 0;  // total by kind
};

// The counts of a full ray tree; every input is clamped to its least meaningful value (depth 0, one pixel).
RayCost whittedRayCost(const RayCostInputs& inputs);

}  // namespace rt
