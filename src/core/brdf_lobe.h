// A BRDF's lobe as a surface: for light arriving from w_i, the points r(w_o) w_o over the hemisphere of
// outgoing directions with r = f_r(w_i, w_o) cos(theta_o), the share of the light that leaves towards each
// w_o per unit solid angle. A Lambertian lobe is a sphere resting on the surface; Phong's and Ward's bulge
// about the mirror direction. An ideal mirror has no finite lobe: its delta is drawn as a spike.
#pragma once

#include <vector>

#include "core/brdf.h"

namespace rt {

struct BrdfLobe {
  std::vector<Polygon> triangles;  // the surface, each counter-clockwise seen from outside
  std::vector<double> values;      // f_r cos(theta_o) at each triangle's centroid direction (1/sr)
  double peak = 0;                 // the largest f_r cos(theta_o) over the sampled directions
  double scale = 0;                // metres per 1/sr as drawn
};

// The lobe drawn so that its farthest point is `size` from the origin (the mirror's spike: deltaReflectance
// times `size`). The directions are sampled about the lobe's axis (the mirror direction, or the normal for a
// Lambertian lobe), `rings` of them denser near the axis and `sectors` around it, so that a narrow lobe
// (q = 128) is as smooth as a wide one.
BrdfLobe brdfLobe(const Brdf& brdf, const Vec3& wi, double size = 1.0, int rings = 48, int sectors = 64);

// A thin square prism from `from` to `to` of half-width `radius`, its four sides facing outwards: an arrow's
// shaft for the incoming ray, the normal or the mirror's spike.
std::vector<Polygon> prism(const Vec3& from, const Vec3& to, double radius);

}  // namespace rt
