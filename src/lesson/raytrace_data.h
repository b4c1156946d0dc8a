// What a raytrace step computes: Whitted pictures of the step's scene with the step's settings and with the
// settings the figures compare (one shadow ray against many, epsilon 0 and too large), the radiosity
// solution's picture from the same camera, one pixel's ray tree, and the rays counted against the cost
// formula over a range of depths. The viz layer draws them; the numbers are also the step's placeholders.
#pragma once

#include <vector>

#include "core/io/rgb_image.h"
#include "core/raytrace/ray_tree.h"

namespace rt::lesson {

struct RayTraceData {
  RgbImage whitted;                        // the step's settings
  RgbImage radiosity;                      // the solution's flat elements through the same camera
  RgbImage hard;                           // one shadow ray per light, otherwise the step's settings
  RgbImage epsilonZero, epsilonLarge;      // one shadow ray, epsilon 0 and largeEpsilon
  RgbImage epsilonStep;                    // one shadow ray, the step's epsilon
  RgbImage idealMirrors;                   // the step's settings with gloss 0 (the glossy view)
  RgbImage pinhole;                        // the step's settings through a pinhole (the focus view)
  double aperture = 0, focusDistance = 0;  // the lens's radius and the plane of focus it used
  RgbImage still;                          // the step's settings without motion (the motion view)
  double motion = 0;                       // how far the moving surfaces travel while the shutter is open
  double gloss = 0;
  int pixelSamples = 1;
  double epsilon = 0, largeEpsilon = 0;
  int shadowRays = 1, depth = 0, lights = 0;
  RayTree tree;  // of pixel (pixelX, pixelY)
  int pixelX = 0, pixelY = 0;
  // Rays per pixel against the depth limit: the full tree's formula and what the tracer counted.
  std::vector<double> depths, formula, counted;
  // The path tracer limited to 0, 1, 2 diffuse bounces and unlimited (-1), `paths` per pixel.
  std::vector<int> bounceLimits;
  std::vector<RgbImage> pathBounces;
  int paths = 0;
};

}  // namespace rt::lesson
