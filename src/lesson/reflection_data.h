// What a reflection step computes: the BRDF the step's keys choose, its lobe for the step's incidence as a
// surface, its directional albedo against incidence (energy conservation) and Phong's cos^q for q = 1 ...
// 128; with a scene, the scene lit by Phong local illumination plus an ambient term and its radiosity
// solution, both through the scene's camera. The viz layer draws these; the numbers are also the step's
// placeholders.
#pragma once

#include <memory>
#include <vector>

#include "core/brdf.h"
#include "core/brdf_lobe.h"
#include "core/io/rgb_image.h"
#include "core/pathtrace/local_illumination.h"
#include "core/scene.h"

namespace rt::lesson {

// What a change of the ambient light leaves as it is: the parts of the local picture (the ambient term is
// added to them) and the radiosity picture. Kept by the step runner, shared by the runs that differ only in
// the ambient light.
struct LitPictures {
  LocalIlluminationParts local;
  RgbImage radiosity;
};

struct ReflectionData {
  Brdf brdf;
  double incidenceDegrees = 0;
  Vec3 wi = Vec3::UnitZ();  // towards the light, in the surface's frame (z the normal)
  BrdfLobe lobe;
  Scene lobeScene;  // the lobe, the surface, the normal and the incoming ray, as patches to draw
  // Albedo against incidence (degrees), in the plane of x.
  std::vector<double> incidences, albedo;
  // Phong's cos^q(alpha) against alpha (degrees), one curve per exponent.
  std::vector<double> exponents, angles;
  std::vector<std::vector<double>> cosinePowers;
  // With a scene: Phong local illumination plus ambient, and the radiosity solution, through its camera.
  RgbImage local, radiosity;
  Rgb ambient = Rgb::Zero();
  std::shared_ptr<const LitPictures> lit;  // what `local` and `radiosity` were made from
};

}  // namespace rt::lesson
