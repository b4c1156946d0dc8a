// Local illumination of a scene through a camera, as renderers before global illumination drew it: at the
// point each pixel sees, the light arriving straight from the emitters (shadow rays to stratified points on
// them, so the shadows are soft), reflected by a Phong BRDF, plus a constant ambient term that stands in for
// every interreflection. No light that bounced off another surface is traced.
#pragma once

#include "core/io/rgb_image.h"
#include "core/pathtrace/tracing_scene.h"
#include "core/scene.h"

namespace rt {

struct LocalIlluminationOptions {
  // The surfaces' Phong BRDF per channel: makeBrdf(phong, rho, specularFraction, exponent, 1) with rho the
  // surface's reflectance, so that a fraction 0 is Lambertian and k_d + k_s = rho conserves energy.
  double specularFraction = 0.0;
  double exponent = 16.0;
  Rgb ambient = Rgb::Zero();  // the ambient radiosity (W/m^2), reflected as rho * ambient
  int lightSamples = 16;      // shadow rays per pixel to the emitters
  int pixelSamples = 1;       // jittered rays per pixel
};

// The two parts of the picture below, per pixel and averaged over its samples: `direct`, the light from the
// emitters (an emitter's own E included), and `reflectance`, the rho of the surfaces seen, which the ambient
// radiosity is reflected by. The ambient term is a constant: a new one needs withAmbient, not a new render.
struct LocalIlluminationParts {
  RgbImage direct, reflectance;
};
LocalIlluminationParts renderLocalIlluminationParts(const TracingScene& scene, const Camera& camera,
                                                    int width, int height,
                                                    const LocalIlluminationOptions& options);
// direct + reflectance * ambient, per pixel and channel.
RgbImage withAmbient(const LocalIlluminationParts& parts, const Rgb& ambient);

// Per pixel pi L towards the camera (W/m^2, so that a Lambertian surface shows its radiosity, comparable
// pixel by pixel with the radiosity solution's image): an emitter shows E, a reflecting surface
// pi sum over light samples of f_r (E / pi) cos(theta) cos(theta') / r^2 A / n + rho ambient; the back of a
// polygon and nothing are black. Deterministic; TBB parallel. withAmbient(renderLocalIlluminationParts(...),
// options.ambient).
RgbImage renderLocalIllumination(const TracingScene& scene, const Camera& camera, int width, int height,
                                 const LocalIlluminationOptions& options);

}  // namespace rt
