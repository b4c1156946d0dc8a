// Pictures of a radiosity solution that can be compared pixel by pixel with the path tracer's: the elements'
// flat B seen through the same camera model, the difference of two images, and the error of an image against
// a noisy reference, with the reference's own noise taken out and a confidence interval.
#pragma once

#include "core/formfactor/ray_scene.h"
#include "core/io/rgb_image.h"
#include "core/mesh.h"
#include "core/pathtrace/path_tracer.h"

namespace rt {

// Per pixel the mean B of the elements that `samples` jittered rays through it reach first (front sides;
// the back of a polygon and nothing are black), as the path tracer's images are sampled. TBB parallel.
RgbImage renderElements(const Mesh& mesh, const RgbField& B, const RayScene& rays, const Camera& camera,
                        int width, int height, int samples = 4);

struct ImageError {
  double rmsDifference = 0;   // RMS over pixels and channels of image - reference, over the reference's mean
  double referenceNoise = 0;  // RMS of the reference's standard errors, over the same mean
  // The image's own RMS error (the difference with the reference's noise variance taken out), and a 95 %
  // interval for it from the spread over pixels.
  double error = 0, low = 0, high = 0;
};

ImageError compareToReference(const RgbImage& image, const TracedImage& reference);

// |a - b| per pixel and channel.
RgbImage absoluteDifference(const RgbImage& a, const RgbImage& b);

// The largest channel of each pixel as a shade from black (0) to white (`full` and above), for looking at an
// error image with a PPM viewer.
RgbImage greyOfLargestChannel(const RgbImage& image, double full);

}  // namespace rt
