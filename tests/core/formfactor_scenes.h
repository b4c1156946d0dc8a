// Small scenes built in code for the form-factor tests: closed boxes (inward faces), a box with a block
// inside (occlusion), two facing squares.
#pragma once

#include <algorithm>
#include <string>

#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"
#include "core/polygon.h"

namespace rt::test {

inline void addQuad(Scene& scene, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                    bool emitter = false) {
  Patch p;
  p.vertices = {a, b, c, d};
  const Vec3 n = newellNormal(p.vertices);
  p.normal = n.normalized();
  p.area = 0.5 * n.norm();
  p.surface = emitter ? 1 : 0;
  scene.patches.push_back(p);
}

// The first patch of the surface named `surface`, or -1.
inline int patchOf(const Scene& scene, const std::string& surface) {
  for (std::size_t p = 0; p < scene.patches.size(); ++p)
    if (scene.surfaces[static_cast<std::size_t>(scene.patches[p].surface)].name == surface)
      return static_cast<int>(p);
  return -1;
}

inline Scene emptyScene() {
  Scene s;
  s.materials.push_back({"grey", Rgb(0.5, 0.5, 0.5), Rgb(0, 0, 0)});
  s.materials.push_back({"light", Rgb(0.2, 0.2, 0.2), Rgb(1, 1, 1)});
  s.surfaces.push_back({"walls", 0});
  s.surfaces.push_back({"light", 1});
  return s;
}

// Axis-aligned box [0,lx] x [0,ly] x [0,lz] with `outward` false: six faces facing inward (closed enclosure);
// true: facing outward (a solid block).
inline void addBox(Scene& s, const Vec3& lo, const Vec3& hi, bool outward, bool emitterTop = false) {
  const double x0 = lo.x(), y0 = lo.y(), z0 = lo.z(), x1 = hi.x(), y1 = hi.y(), z1 = hi.z();
  auto quad = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d, bool emitter = false) {
    if (outward)
      addQuad(s, a, d, c, b, emitter);
    else
      addQuad(s, a, b, c, d, emitter);
  };
  quad({x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0});              // bottom, inward +z
  quad({x0, y0, z1}, {x0, y1, z1}, {x1, y1, z1}, {x1, y0, z1}, emitterTop);  // top, inward -z
  quad({x0, y0, z0}, {x0, y0, z1}, {x1, y0, z1}, {x1, y0, z0});              // y0, inward +y
  quad({x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1});              // y1, inward -y
  quad({x0, y0, z0}, {x0, y1, z0}, {x0, y1, z1}, {x0, y0, z1});              // x0, inward +x
  quad({x1, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x1, y1, z0});              // x1, inward -x
}

inline Scene closedBox(double lx, double ly, double lz) {
  Scene s = emptyScene();
  addBox(s, Vec3::Zero(), Vec3(lx, ly, lz), false, true);
  return s;
}

// A unit room with a block standing on the floor: the floor-ceiling pairs above the block are occluded.
inline Scene roomWithBlock() {
  Scene s = closedBox(1, 1, 1);
  addBox(s, Vec3(0.3, 0.3, 0), Vec3(0.7, 0.7, 0.4), true);
  s.patches.erase(s.patches.begin() + 6);  // the block's bottom lies on the floor and faces down: drop it
  return s;
}

inline Mesh meshOf(const Scene& s, int subdivide) {
  MeshOptions o;
  if (subdivide > 1) {
    o.mode = MeshOptions::Mode::Count;
    o.count = subdivide;
  }
  return buildMesh(s, o);
}

// F of `mesh` by the registered method `method`, its stats in *statsOut when asked for.
inline FormFactorMatrix runMethod(const std::string& method, const Mesh& mesh, FormFactorOptions options = {},
                                  FormFactorStats* statsOut = nullptr) {
  FormFactorStats stats;
  FormFactorMatrix F = makeFormFactorMethod(method)->compute(mesh, options, noProgress(), stats);
  if (statsOut) *statsOut = stats;
  return F;
}

// A method's name as a test parameter's name, which takes letters, digits and underscores only.
inline std::string testNameOf(std::string method) {
  std::replace(method.begin(), method.end(), '-', '_');
  return method;
}

}  // namespace rt::test
