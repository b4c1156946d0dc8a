#include "lesson/step_keys_chapters.h"

#include "core/brdf.h"

namespace rt::lesson {
namespace {

using P = StepParameters;

const std::vector<std::string>& brdfModels() {
  static const std::vector<std::string> values = brdfModelNames();
  return values;
}

}  // namespace

void addChapterKeys(std::vector<StepKey>& t) {
  t.push_back(
      {.name = "patch-distance",
       .type = KeyType::Double,
       .min = 0.05,
       .max = 100,
       .defaultText = "1",
       .label = "Patch distance (m)",
       .tooltip =
           "Radiometry stage: the distance from the point to the centre of the square patch (and of the "
           "square source), in metres.",
       .control = true,
       .decimals = 2,
       .step = 0.1,
       .stages = {Stage::Radiometry},
       .slot = &P::patchDistance});
  t.push_back(
      {.name = "patch-tilt",
       .type = KeyType::Double,
       .min = 0,
       .max = 89,
       .defaultText = "0",
       .label = "Patch tilt (degrees)",
       .tooltip =
           "Radiometry stage: the angle between the patch's normal and the line from its centre to the "
           "point; the patch turns about one of its edges' directions.",
       .control = true,
       .decimals = 1,
       .step = 5,
       .stages = {Stage::Radiometry},
       .slot = &P::patchTilt});
  t.push_back({.name = "patch-size",
               .type = KeyType::Double,
               .min = 0.01,
               .max = 10,
               .defaultText = "0.5",
               .label = "Patch side (m)",
               .tooltip =
                   "Radiometry stage: the side of the square patch, and of the square source compared with a "
                   "point source of the same power, in metres.",
               .control = true,
               .decimals = 2,
               .step = 0.05,
               .stages = {Stage::Radiometry},
               .slot = &P::patchSize});
  t.push_back({.name = "ray-depth",
               .type = KeyType::Int,
               .min = 0,
               .max = 12,
               .defaultText = "3",
               .label = "Ray depth",
               .tooltip =
                   "Raytrace stage: the mirror reflections a ray tree follows at most (0: primary and shadow "
                   "rays only).",
               .control = true,
               .stages = {Stage::RayTrace},
               .slot = &P::rayDepth});
  t.push_back({.name = "shadow-rays",
               .type = KeyType::Int,
               .min = 1,
               .max = 1024,
               .defaultText = "16",
               .label = "Shadow rays",
               .tooltip =
                   "Raytrace stage: shadow rays from each surface point to each light. One goes to the "
                   "light's centre, a point light with hard shadows; more sample the light's area and soften "
                   "the shadows' edges.",
               .control = true,
               .step = 4,
               .stages = {Stage::RayTrace},
               .slot = &P::shadowRays});
  t.push_back({.name = "ray-epsilon",
               .type = KeyType::Double,
               .min = 0,
               .max = 1e6,
               .defaultText = "0.1",
               .label = "Ray epsilon",
               .tooltip =
                   "Raytrace stage: secondary rays ignore hits closer than this to their start, in the "
                   "scene's units (the Cornell box's are millimetres). 0 lets a ray find the surface it "
                   "leaves (shadow acne); too large lets it skip a nearby blocker (light leaks).",
               .control = true,
               .decimals = 3,
               .step = 0.1,
               .stages = {Stage::RayTrace},
               .slot = &P::rayEpsilon});
  t.push_back({.name = "light-size",
               .type = KeyType::Double,
               .min = 0.1,
               .max = 4,
               .defaultText = "1",
               .label = "Light size",
               .tooltip =
                   "Raytrace stage: every light scaled about its centre by this factor for the shadow rays, "
                   "its power kept: a larger light casts a wider penumbra.",
               .control = true,
               .decimals = 2,
               .step = 0.25,
               .stages = {Stage::RayTrace},
               .slot = &P::lightSize});
  t.push_back(
      {.name = "gloss",
       .type = KeyType::Double,
       .min = 0,
       .max = 10000,
       .defaultText = "0",
       .label = "Gloss exponent",
       .tooltip = "Raytrace stage: the mirrors' Phong exponent q. 0 is an ideal mirror, one reflected ray in "
                  "the mirror direction; q > 0 draws each reflected ray from the lobe cos^q about it "
                  "(glossy reflection): the smaller q, the blurrier the reflection.",
       .control = true,
       .decimals = 0,
       .step = 8,
       .stages = {Stage::RayTrace},
       .slot = &P::gloss});
  t.push_back({.name = "pixel-samples",
               .type = KeyType::Int,
               .min = 1,
               .max = 1024,
               .defaultText = "1",
               .label = "Rays per pixel",
               .tooltip =
                   "Raytrace stage: primary rays per pixel, jittered over its area (antialiasing). Each also "
                   "draws its own shadow-ray points and its own direction in a glossy lobe, so their average "
                   "smooths all three.",
               .control = true,
               .step = 4,
               .stages = {Stage::RayTrace},
               .slot = &P::pixelSamples});
  t.push_back({.name = "aperture",
               .type = KeyType::Double,
               .min = 0,
               .max = 1e6,
               .defaultText = "0",
               .label = "Lens radius",
               .tooltip =
                   "Raytrace stage: the radius of the camera's lens, in the scene's units. 0 is a pinhole, "
                   "everything sharp; above 0 each primary ray starts at its own point of the lens and "
                   "passes through the plane of focus, so only that plane stays sharp (depth of field).",
               .control = true,
               .decimals = 1,
               .step = 5,
               .stages = {Stage::RayTrace},
               .slot = &P::aperture});
  t.push_back({.name = "focus-distance",
               .type = KeyType::Double,
               .min = 0,
               .max = 1e9,
               .defaultText = "0",
               .label = "Focus distance",
               .tooltip = "Raytrace stage: the distance of the lens's plane of focus along the view "
                          "direction, in the scene's units; points there are sharp. 0 is the distance to "
                          "the camera's target.",
               .control = true,
               .decimals = 0,
               .step = 50,
               .stages = {Stage::RayTrace},
               .slot = &P::focusDistance});
  t.push_back({.name = "pixel-x",
               .type = KeyType::Int,
               .min = 0,
               .max = 2047,
               .defaultText = "64",
               .label = "Traced pixel x",
               .tooltip =
                   "Raytrace stage: the column (from the left, below image-size) of the pixel whose ray tree "
                   "is drawn.",
               .control = true,
               .step = 4,
               .stages = {Stage::RayTrace},
               .slot = &P::pixelX});
  t.push_back({.name = "pixel-y",
               .type = KeyType::Int,
               .min = 0,
               .max = 2047,
               .defaultText = "64",
               .label = "Traced pixel y",
               .tooltip =
                   "Raytrace stage: the row (from the top, below image-size) of the pixel whose ray tree is "
                   "drawn.",
               .control = true,
               .step = 4,
               .stages = {Stage::RayTrace},
               .slot = &P::pixelY});
  t.push_back({.name = "mirrors",
               .type = KeyType::Text,
               .label = "Mirrors",
               .tooltip =
                   "Raytrace stage: the surfaces (comma-separated names) that reflect as mirrors; the others "
                   "are diffuse.",
               .stages = {Stage::RayTrace},
               .slot = &P::mirrors});
  t.push_back({.name = "moving",
               .type = KeyType::Text,
               .label = "Moving surfaces",
               .tooltip =
                   "Raytrace stage: the surfaces (comma-separated names) that move while the shutter is "
                   "open, by `motion`; lights may not move.",
               .stages = {Stage::RayTrace},
               .slot = &P::moving});
  t.push_back({.name = "motion",
               .type = KeyType::Double,
               .min = -1e6,
               .max = 1e6,
               .defaultText = "0",
               .label = "Motion",
               .tooltip =
                   "Raytrace stage: how far the `moving` surfaces travel along the scene's x axis while "
                   "the shutter is open, in the scene's units, at a constant speed and centred on where "
                   "the scene puts them. Each primary ray sees them at its own time in the shutter "
                   "interval (motion blur); 0 stands still.",
               .control = true,
               .decimals = 0,
               .step = 20,
               .stages = {Stage::RayTrace},
               .slot = &P::motion});
  t.push_back(
      {.name = "brdf-model",
       .type = KeyType::Choice,
       .choices = &brdfModels,
       .defaultText = "phong",
       .label = "BRDF model",
       .tooltip = "Reflection stage: the BRDF whose lobe is drawn: lambertian (ideal diffuse), mirror (ideal "
                  "specular, a delta), phong (normalised) or ward (anisotropic).",
       .control = true,
       .stages = {Stage::Reflection},
       .slot = &P::brdfModel});
  t.push_back(
      {.name = "phong-exponent",
       .type = KeyType::Double,
       .min = 0,
       .max = 10000,
       .defaultText = "16",
       .label = "Phong exponent q",
       .tooltip =
           "Reflection stage: Phong's exponent q, the sharpness of the highlight (Ward's lobe takes the "
           "matching spread alpha = sqrt(2 / (q + 2))).",
       .control = true,
       .decimals = 1,
       .step = 4,
       .stages = {Stage::Reflection},
       .slot = &P::phongExponent});
  t.push_back({.name = "specular-fraction",
               .type = KeyType::Double,
               .min = 0,
               .max = 1,
               .defaultText = "0.3",
               .label = "Specular fraction",
               .tooltip =
                   "Reflection stage: the share of the reflectance that is specular, k_s / (k_d + k_s); the "
                   "rest is diffuse, so k_d + k_s stays the surface's reflectance.",
               .control = true,
               .decimals = 2,
               .step = 0.05,
               .stages = {Stage::Reflection},
               .slot = &P::specularFraction});
  t.push_back(
      {.name = "anisotropy",
       .type = KeyType::Double,
       .min = 1,
       .max = 16,
       .defaultText = "1",
       .label = "Anisotropy",
       .tooltip = "Reflection stage: Ward's lobe is alpha_x / alpha_y times wider along the surface's x axis "
                  "than along y (1: isotropic).",
       .control = true,
       .decimals = 1,
       .step = 0.5,
       .stages = {Stage::Reflection},
       .slot = &P::anisotropy});
  t.push_back({.name = "incidence-angle",
               .type = KeyType::Double,
               .min = 0,
               .max = 89,
               .defaultText = "45",
               .label = "Incidence (degrees)",
               .tooltip =
                   "Reflection stage: the angle between the surface's normal and the direction the light "
                   "arrives from, in the plane of the surface's x axis.",
               .control = true,
               .decimals = 1,
               .step = 5,
               .stages = {Stage::Reflection},
               .slot = &P::incidenceAngle});
}

}  // namespace rt::lesson
