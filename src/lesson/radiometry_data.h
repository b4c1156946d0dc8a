// What a radiometry step computes: a square patch seen from a point (its solid angle, exactly and by the
// small-patch approximation), the irradiance an isotropic point source at the point gives the patch against
// its tilt (the cosine law), and the irradiance a point emitter and a square emitter of the same power give a
// point facing them against distance (the inverse-square law and where it fails). The viz layer draws these;
// the numbers are also the step's placeholders.
#pragma once

#include <vector>

#include "core/vec.h"

namespace rt::lesson {

struct RadiometryData {
  // The step's geometry: the point at the origin, the patch's centre on the +z axis.
  Vec3 point = Vec3::Zero();
  Polygon patch;  // CCW seen from the point's side
  double distance = 0, tiltDegrees = 0, side = 0;
  double solidAngle = 0;  // exact (core/radiometry.h)
  double smallPatch = 0;  // A cos(theta) / r^2
  double power = 0;       // Phi of the sources, W
  double intensity = 0;   // of the isotropic point source, Phi / (4 pi), W/sr
  // The cosine law: irradiance on the patch at the step's distance against its tilt (degrees), by
  // I cos(theta) / r^2 and exactly (I Omega / A: the patch's mean).
  std::vector<double> tilts, cosineLaw, patchMean;
  // The inverse-square law: on a point facing the sources, at these distances (m), from a Lambertian point
  // emitter of power Phi (Phi / (pi r^2)) and from a Lambertian square of side `side` and the same power
  // ((Phi / side^2) F, with F the exact point-to-square form factor).
  std::vector<double> distances, pointSource, squareSource;
  double onePercentDistance = 0;  // beyond it the point law is within 1% of the square's
};

}  // namespace rt::lesson
