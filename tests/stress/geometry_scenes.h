// Small near-singular scenes built in code for the stress tests, each at any scale: a closed box whose faces
// are cut into 1000:1 slivers along their edges (abutting elements, slivers, a furnace), two plates a tiny
// gap apart, and a room with a block floating a tiny gap above its floor. Every coordinate is multiplied by
// `scale`; form factors, and with them B, do not depend on it.
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/polygon.h"

namespace rt::test {

// Appends a material and a surface using it; returns the surface index.
inline int addSurface(Scene& scene, const std::string& name, const Rgb& reflectance, const Rgb& emission) {
  scene.materials.push_back(Material{name, reflectance, emission});
  scene.surfaces.push_back(Surface{name, static_cast<int>(scene.materials.size()) - 1});
  return static_cast<int>(scene.surfaces.size()) - 1;
}

// A quad a, b, c, d (counter-clockwise seen from the side it faces).
inline void addQuadPatch(Scene& scene, int surface, const Vec3& a, const Vec3& b, const Vec3& c,
                         const Vec3& d) {
  Patch p;
  p.vertices = {a, b, c, d};
  p.normal = newellNormal(p.vertices).normalized();
  p.area = polygonArea(p.vertices);
  p.surface = surface;
  scene.patches.push_back(p);
}

// The quad a, b, c, d cut along a -> b at fraction t: a sliver of width t next to the edge a-d, and the rest.
inline void addSplitQuad(Scene& scene, int surface, const Vec3& a, const Vec3& b, const Vec3& c,
                         const Vec3& d, double t) {
  const Vec3 ab = a + t * (b - a), dc = d + t * (c - d);
  addQuadPatch(scene, surface, a, ab, dc, d);
  addQuadPatch(scene, surface, ab, b, c, dc);
}

// The six faces of the box [lo, hi]: facing inward (a closed room) or outward (a solid block). `quad`
// receives each face counter-clockwise seen from the side it faces, the face index (0 bottom, 1 top, 2..5
// sides) first.
template <typename Quad>
void forEachBoxFace(const Vec3& lo, const Vec3& hi, bool outward, Quad&& quad) {
  const double x0 = lo.x(), y0 = lo.y(), z0 = lo.z(), x1 = hi.x(), y1 = hi.y(), z1 = hi.z();
  auto face = [&](int index, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    if (outward)
      quad(index, a, d, c, b);
    else
      quad(index, a, b, c, d);
  };
  face(0, {x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0});  // bottom, inward +z
  face(1, {x0, y0, z1}, {x0, y1, z1}, {x1, y1, z1}, {x1, y0, z1});  // top, inward -z
  face(2, {x0, y0, z0}, {x0, y0, z1}, {x1, y0, z1}, {x1, y0, z0});  // y0, inward +y
  face(3, {x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1});  // y1, inward -y
  face(4, {x0, y0, z0}, {x0, y1, z0}, {x0, y1, z1}, {x0, y0, z1});  // x0, inward +x
  face(5, {x1, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x1, y1, z0});  // x1, inward -x
}

// Closed unit room, every face cut into a sliver `sliver` wide (1000:1 for 1e-3) and the rest; every face
// with reflectance rho and emission E: the furnace, B = E / (1 - rho) whatever the geometry.
inline Scene sliverFurnace(double scale, double rho, double emission, double sliver = 1e-3) {
  Scene scene;
  scene.name = "sliver furnace";
  const int walls = addSurface(scene, "walls", Rgb::Constant(rho), Rgb::Constant(emission));
  forEachBoxFace(Vec3::Zero(), Vec3::Constant(scale), false,
                 [&](int, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
                   addSplitQuad(scene, walls, a, b, c, d, sliver);
                 });
  return scene;
}

// Two unit squares facing each other `gap` apart; the lower one emits.
inline Scene gapPlates(double scale, double gap) {
  Scene scene;
  scene.name = "plates a gap apart";
  const int light = addSurface(scene, "light", Rgb(0.8, 0.5, 0.2), Rgb(1.0, 1.0, 1.0));
  const int wall = addSurface(scene, "wall", Rgb(0.9, 0.6, 0.3), Rgb::Zero());
  const double s = scale, h = gap * scale;
  addQuadPatch(scene, light, {0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0});  // faces +z
  addQuadPatch(scene, wall, {0, 0, h}, {0, s, h}, {s, s, h}, {s, 0, h});   // faces -z
  return scene;
}

// A closed unit room lit by its ceiling, a red and a green wall, and a solid block floating `gap` above the
// floor (its bottom face included): the floor under the block and the block's bottom see almost only each
// other and only the light that creeps through the gap.
inline Scene floatingBlockRoom(double scale, double gap) {
  Scene scene;
  scene.name = "block above the floor";
  const int white = addSurface(scene, "white", Rgb(0.7, 0.7, 0.7), Rgb::Zero());
  const int red = addSurface(scene, "red", Rgb(0.6, 0.1, 0.1), Rgb::Zero());
  const int green = addSurface(scene, "green", Rgb(0.1, 0.6, 0.1), Rgb::Zero());
  const int light = addSurface(scene, "light", Rgb(0.5, 0.5, 0.5), Rgb(4.0, 4.0, 4.0));
  const int block = addSurface(scene, "block", Rgb(0.5, 0.5, 0.5), Rgb::Zero());
  forEachBoxFace(Vec3::Zero(), Vec3::Constant(scale), false,
                 [&](int face, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
                   const int surface = face == 1 ? light : face == 4 ? red : face == 5 ? green : white;
                   addQuadPatch(scene, surface, a, b, c, d);
                 });
  forEachBoxFace(scale * Vec3(0.3, 0.3, gap), scale * Vec3(0.7, 0.7, 0.4 + gap), true,
                 [&](int, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
                   addQuadPatch(scene, block, a, b, c, d);
                 });
  return scene;
}

inline Mesh meshSplit(const Scene& scene, int count) {
  MeshOptions o;
  o.mode = MeshOptions::Mode::Count;
  o.count = count;
  return buildMesh(scene, o);
}

}  // namespace rt::test
