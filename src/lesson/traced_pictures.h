// What a pathtrace step computes beside the radiosity solution: the same equation solved by the path tracer
// (no mesh) as an image, the radiosity and two-pass images from the same camera, how the path tracer's
// noise falls with its paths per pixel, and where each method's time goes. The viz layer draws them.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/io/rgb_image.h"
#include "core/pathtrace/path_tracer.h"
#include "core/power_law.h"

namespace rt::lesson {

// The path tracer's noise at one number of paths per pixel, relative to the image's mean: `measured` from
// two images with different seeds (the RMS of their difference over sqrt 2), `reported` the RMS of the
// tracer's own per-pixel standard errors.
struct NoisePoint {
  int paths = 0;
  double measured = 0;
  double reported = 0;
};

struct TracedPictures {
  TracedImage pathTraced;  // the reference, `paths` per pixel
  RgbImage radiosity;      // the solution's flat elements through the same camera
  RgbImage twoPass;        // direct light at the point plus a final gather from the solution
  std::vector<NoisePoint> noise;
  double slope = 0;                      // least-squares slope of log(measured noise) against log(paths)
  double mean = 0;                       // mean over pixels and channels of the path-traced image (W/m^2)
  std::map<std::string, double> values;  // the step's numbers about them (rms.radiosity, seconds.trace...)
};

using rt::logLogSlope;  // core/power_law.h

// Mean over pixels and channels of an image (0 for an empty one).
double imageMean(const RgbImage& image);

}  // namespace rt::lesson
