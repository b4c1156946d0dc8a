// Small hand-built scenes for the refinement tests: a square light over a square occluder over a floor
// (shadow boundaries known in closed form), a closed room with a light and a blocker (energy balance), and
// the Cornell box from tests/data/refdata geometry (oriented inwards, ceiling around the light's hole, left
// wall as two triangles).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "core/polygon.h"
#include "core/scene.h"

namespace rt::test {

inline int addMaterial(Scene& s, const std::string& name, Rgb reflectance, Rgb emission = Rgb::Zero()) {
  s.materials.push_back({name, reflectance, emission});
  s.surfaces.push_back({name, static_cast<int>(s.materials.size() - 1)});
  return static_cast<int>(s.surfaces.size() - 1);
}

// Adds a patch; when `towards` is given the vertex order is flipped if needed so that the normal points at
// it.
inline void addPatch(Scene& s, int surface, Polygon vertices, const Vec3* towards = nullptr,
                     bool away = false) {
  Vec3 n = newellNormal(vertices);
  if (towards) {
    const bool facing = (*towards - polygonCentroid(vertices)).dot(n) > 0;
    if (facing == away) {
      std::reverse(vertices.begin(), vertices.end());
      n = -n;
    }
  }
  Patch p;
  p.vertices = std::move(vertices);
  p.normal = n.normalized();
  p.area = polygonArea(p.vertices);
  p.surface = surface;
  s.patches.push_back(std::move(p));
}

inline Polygon square(double cx, double cy, double z, double half) {
  return {Vec3(cx - half, cy - half, z), Vec3(cx + half, cy - half, z), Vec3(cx + half, cy + half, z),
          Vec3(cx - half, cy + half, z)};
}

// Light [-0.25,0.25]^2 at z=2 facing down, occluder [-0.5,0.5]^2 at z=1 facing up, floor [-2,2]^2 at z=0
// facing up. Shadow lines on the floor: umbra |x|,|y| = 0.75, outer penumbra |x|,|y| = 1.25.
inline Scene shadowScene(double floorReflectance = 0.5) {
  Scene s;
  s.name = "shadow";
  const int light = addMaterial(s, "light", Rgb::Constant(0.0), Rgb::Constant(100.0));
  const int grey = addMaterial(s, "grey", Rgb::Constant(floorReflectance));
  const Vec3 below(0, 0, -10), above(0, 0, 10);
  addPatch(s, light, square(0, 0, 2, 0.25), &below);
  addPatch(s, grey, square(0, 0, 1, 0.5), &above);
  addPatch(s, grey, square(0, 0, 0, 2.0), &above);
  return s;
}

// A closed cube [0,2]^3 facing inwards with a square light in the ceiling's middle (coplanar, the ceiling as
// four quads around it) and a floating box [0.6,1.4]^2 x [0.6,1.0] facing outwards. Closed: all emitted power
// is absorbed.
inline Scene closedRoom() {
  Scene s;
  s.name = "room";
  const int light = addMaterial(s, "light", Rgb::Constant(0.3), Rgb::Constant(10.0));
  const int white = addMaterial(s, "white", Rgb(0.7, 0.6, 0.5));
  const int red = addMaterial(s, "red", Rgb(0.6, 0.1, 0.1));
  const Vec3 centre(1, 1, 1);
  auto quad = [](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return Polygon{a, b, c, d}; };
  addPatch(s, light, square(1, 1, 2, 0.3), &centre);
  addPatch(s, white, square(1, 1, 0, 1), &centre);  // floor
  // ceiling around the light: four quads
  addPatch(s, white, quad({0, 0, 2}, {2, 0, 2}, {1.3, 0.7, 2}, {0.7, 0.7, 2}), &centre);
  addPatch(s, white, quad({2, 0, 2}, {2, 2, 2}, {1.3, 1.3, 2}, {1.3, 0.7, 2}), &centre);
  addPatch(s, white, quad({2, 2, 2}, {0, 2, 2}, {0.7, 1.3, 2}, {1.3, 1.3, 2}), &centre);
  addPatch(s, white, quad({0, 2, 2}, {0, 0, 2}, {0.7, 0.7, 2}, {0.7, 1.3, 2}), &centre);
  addPatch(s, red, quad({0, 0, 0}, {0, 2, 0}, {0, 2, 2}, {0, 0, 2}), &centre);
  addPatch(s, white, quad({2, 0, 0}, {2, 2, 0}, {2, 2, 2}, {2, 0, 2}), &centre);
  addPatch(s, white, quad({0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}), &centre);
  addPatch(s, white, quad({0, 2, 0}, {2, 2, 0}, {2, 2, 2}, {0, 2, 2}), &centre);
  const Vec3 box(1, 1, 0.8);
  addPatch(s, white, square(1, 1, 1.0, 0.4), &box, true);
  addPatch(s, white, square(1, 1, 0.6, 0.4), &box, true);
  addPatch(s, white, quad({0.6, 0.6, 0.6}, {1.4, 0.6, 0.6}, {1.4, 0.6, 1.0}, {0.6, 0.6, 1.0}), &box, true);
  addPatch(s, white, quad({0.6, 1.4, 0.6}, {1.4, 1.4, 0.6}, {1.4, 1.4, 1.0}, {0.6, 1.4, 1.0}), &box, true);
  addPatch(s, white, quad({0.6, 0.6, 0.6}, {0.6, 1.4, 0.6}, {0.6, 1.4, 1.0}, {0.6, 0.6, 1.0}), &box, true);
  addPatch(s, white, quad({1.4, 0.6, 0.6}, {1.4, 1.4, 0.6}, {1.4, 1.4, 1.0}, {1.4, 0.6, 1.0}), &box, true);
  return s;
}

// The Cornell box in millimetres, with the RGB reflectances of the Mitsuba example and a light emitting
// pi x (18.387, 10.9873, 2.75357) W/m^2.
inline Scene cornellBox() {
  Scene s;
  s.name = "cornell-box";
  s.unit = "mm";
  const int light =
      addMaterial(s, "light", Rgb(0.78, 0.78, 0.78), 3.14159265358979 * Rgb(18.387, 10.9873, 2.75357));
  const int white = addMaterial(s, "white", Rgb(0.885809, 0.698859, 0.666422));
  const int red = addMaterial(s, "red", Rgb(0.570068, 0.0430135, 0.0443706));
  const int green = addMaterial(s, "green", Rgb(0.105421, 0.37798, 0.076425));
  const Vec3 inside(278, 274, 280);
  const Vec3 below(278, 0, 280);
  addPatch(s, light,
           {{343.0, 548.8, 227.0}, {343.0, 548.8, 332.0}, {213.0, 548.8, 332.0}, {213.0, 548.8, 227.0}},
           &below);
  addPatch(s, white, {{552.8, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 559.2}, {549.6, 0.0, 559.2}}, &inside);
  // Ceiling with the light's hole: four quads between the outer rectangle and the hole.
  const Vec3 c0(556.0, 548.8, 0.0), c1(556.0, 548.8, 559.2), c2(0.0, 548.8, 559.2), c3(0.0, 548.8, 0.0);
  const Vec3 h0(343.0, 548.8, 227.0), h1(343.0, 548.8, 332.0), h2(213.0, 548.8, 332.0),
      h3(213.0, 548.8, 227.0);
  addPatch(s, white, {c0, c1, h1, h0}, &below);
  addPatch(s, white, {c1, c2, h2, h1}, &below);
  addPatch(s, white, {c2, c3, h3, h2}, &below);
  addPatch(s, white, {c3, c0, h0, h3}, &below);
  addPatch(s, white, {{549.6, 0.0, 559.2}, {0.0, 0.0, 559.2}, {0.0, 548.8, 559.2}, {556.0, 548.8, 559.2}},
           &inside);
  addPatch(s, green, {{0.0, 0.0, 559.2}, {0.0, 0.0, 0.0}, {0.0, 548.8, 0.0}, {0.0, 548.8, 559.2}}, &inside);
  addPatch(s, red, {{552.8, 0.0, 0.0}, {549.6, 0.0, 559.2}, {556.0, 548.8, 559.2}}, &inside);
  addPatch(s, red, {{552.8, 0.0, 0.0}, {556.0, 548.8, 559.2}, {556.0, 548.8, 0.0}}, &inside);
  const std::vector<Polygon> shortBlock = {
      {{130.0, 165.0, 65.0}, {82.0, 165.0, 225.0}, {240.0, 165.0, 272.0}, {290.0, 165.0, 114.0}},
      {{290.0, 0.0, 114.0}, {290.0, 165.0, 114.0}, {240.0, 165.0, 272.0}, {240.0, 0.0, 272.0}},
      {{130.0, 0.0, 65.0}, {130.0, 165.0, 65.0}, {290.0, 165.0, 114.0}, {290.0, 0.0, 114.0}},
      {{82.0, 0.0, 225.0}, {82.0, 165.0, 225.0}, {130.0, 165.0, 65.0}, {130.0, 0.0, 65.0}},
      {{240.0, 0.0, 272.0}, {240.0, 165.0, 272.0}, {82.0, 165.0, 225.0}, {82.0, 0.0, 225.0}}};
  const std::vector<Polygon> tallBlock = {
      {{423.0, 330.0, 247.0}, {265.0, 330.0, 296.0}, {314.0, 330.0, 456.0}, {472.0, 330.0, 406.0}},
      {{423.0, 0.0, 247.0}, {423.0, 330.0, 247.0}, {472.0, 330.0, 406.0}, {472.0, 0.0, 406.0}},
      {{472.0, 0.0, 406.0}, {472.0, 330.0, 406.0}, {314.0, 330.0, 456.0}, {314.0, 0.0, 456.0}},
      {{314.0, 0.0, 456.0}, {314.0, 330.0, 456.0}, {265.0, 330.0, 296.0}, {265.0, 0.0, 296.0}},
      {{265.0, 0.0, 296.0}, {265.0, 330.0, 296.0}, {423.0, 330.0, 247.0}, {423.0, 0.0, 247.0}}};
  const Vec3 shortCentre(186, 82.5, 168.5), tallCentre(368.5, 165, 351.5);
  for (const Polygon& p : shortBlock) addPatch(s, white, p, &shortCentre, true);
  for (const Polygon& p : tallBlock) addPatch(s, white, p, &tallCentre, true);
  return s;
}

}  // namespace rt::test
