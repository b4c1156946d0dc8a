// A thin-lens camera for distributed ray tracing's depth of field (Cook, Porter and Carpenter 1984). A
// pinhole camera sends every primary ray from one point, so everything is sharp. A lens of radius a sends the
// rays of one pixel from points spread over its disc, all through the one point where the pinhole's ray meets
// the plane of focus, at distance f along the view direction: points on that plane stay sharp, and a point at
// depth z is spread over a disc whose diameter, as an angle seen from the lens, is 2 a |1/f - 1/z|.
#pragma once

#include "core/scene.h"

namespace rt {

struct ThinLens {
  double radius = 0;         // the aperture's radius, in scene units (0: a pinhole)
  double focusDistance = 0;  // the plane of focus, along the view direction (0: the camera's target)
};

struct LensRay {
  Vec3 origin, direction;
};

// The focus distance the lens uses: its own, or the distance from the camera to its target.
double focusDistanceOf(const Camera& camera, const ThinLens& lens);

// The primary ray through the lens point drawn from two uniform numbers in [0, 1) (uniform over the disc)
// that reaches the point where the pinhole ray `pinholeDirection` meets the plane of focus.
LensRay thinLensRay(const Camera& camera, const ThinLens& lens, const Vec3& pinholeDirection, double u,
                    double v);

// The diameter, in pixels of an image `height` pixels tall, of the blur disc of a point at `depth` along the
// view direction: 2 a |1/f - 1/z| over the angle one pixel spans at the image's centre.
double blurDiscPixels(const Camera& camera, const ThinLens& lens, int height, double depth);

}  // namespace rt
