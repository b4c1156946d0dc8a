#include "app/builtin_scene.h"

#include <cmath>

#include "core/polygon.h"

namespace rt::app {
namespace {

// Adds a convex patch, ordering its vertices so that its front faces `towards` (a point on the visible side).
void addPatch(Scene& scene, int surface, Polygon polygon, const Vec3& towards) {
  Vec3 normal = newellNormal(polygon).normalized();
  if (normal.dot(towards - polygonCentroid(polygon)) < 0) {
    std::reverse(polygon.begin(), polygon.end());
    normal = -normal;
  }
  Patch patch;
  patch.vertices = std::move(polygon);
  patch.normal = normal;
  patch.area = polygonArea(patch.vertices);
  patch.surface = surface;
  patch.origin = SourceLocation{"<built-in Cornell box>", 0, "/surfaces/" + std::to_string(surface)};
  scene.patches.push_back(std::move(patch));
}

int addSurface(Scene& scene, const std::string& name, int material) {
  scene.surfaces.push_back(Surface{name, material});
  return static_cast<int>(scene.surfaces.size()) - 1;
}

Vec3 mm(double x, double y, double z) {
  return Vec3(x, y, z) / 1000.0;
}

// A block: its top quad at height `top` above the floor; sides face away from its axis.
void addBlock(Scene& scene, int surface, const Polygon& topQuad) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& v : topQuad) centre += v;
  centre /= static_cast<double>(topQuad.size());
  addPatch(scene, surface, topQuad, centre + Vec3(0, 1, 0));
  for (std::size_t i = 0; i < topQuad.size(); ++i) {
    const Vec3& a = topQuad[i];
    const Vec3& b = topQuad[(i + 1) % topQuad.size()];
    const Polygon side{a, b, Vec3(b.x(), 0, b.z()), Vec3(a.x(), 0, a.z())};
    const Vec3 mid = 0.5 * (a + b);
    addPatch(scene, surface, side, mid + (mid - centre).cwiseProduct(Vec3(1, 0, 1)));
  }
}

}  // namespace

Scene builtinCornellBox() {
  Scene scene;
  scene.name = "Cornell box";
  scene.sourceFile = "<built-in Cornell box>";
  scene.unit = "m";
  scene.materials = {
      {"white", Rgb(0.737, 0.728, 0.767), Rgb::Zero()},
      {"red", Rgb(0.642, 0.063, 0.061), Rgb::Zero()},
      {"green", Rgb(0.159, 0.373, 0.101), Rgb::Zero()},
      {"light", Rgb(0.78, 0.78, 0.78), Rgb(17.0, 12.0, 4.0)},
  };
  const Vec3 inside = mm(278, 274, 280);
  addPatch(scene, addSurface(scene, "floor", 0),
           {mm(552.8, 0, 0), mm(0, 0, 0), mm(0, 0, 559.2), mm(549.6, 0, 559.2)}, inside);
  addPatch(scene, addSurface(scene, "ceiling", 0),
           {mm(556, 548.8, 0), mm(556, 548.8, 559.2), mm(0, 548.8, 559.2), mm(0, 548.8, 0)}, inside);
  addPatch(scene, addSurface(scene, "back_wall", 0),
           {mm(549.6, 0, 559.2), mm(0, 0, 559.2), mm(0, 548.8, 559.2), mm(556, 548.8, 559.2)}, inside);
  // The measured left wall is non-planar by 3.2 mm; as two triangles each part is exactly planar.
  const int left = addSurface(scene, "left_wall", 1);
  addPatch(scene, left, {mm(552.8, 0, 0), mm(549.6, 0, 559.2), mm(556, 548.8, 559.2)}, inside);
  addPatch(scene, left, {mm(552.8, 0, 0), mm(556, 548.8, 559.2), mm(556, 548.8, 0)}, inside);
  addPatch(scene, addSurface(scene, "right_wall", 2),
           {mm(0, 0, 559.2), mm(0, 0, 0), mm(0, 548.8, 0), mm(0, 548.8, 559.2)}, inside);
  // The light hangs just below the ceiling, facing down.
  addPatch(scene, addSurface(scene, "light", 3),
           {mm(343, 548.7, 227), mm(343, 548.7, 332), mm(213, 548.7, 332), mm(213, 548.7, 227)},
           mm(278, 0, 280));
  addBlock(scene, addSurface(scene, "short_block", 0),
           {mm(130, 165, 65), mm(82, 165, 225), mm(240, 165, 272), mm(290, 165, 114)});
  addBlock(scene, addSurface(scene, "tall_block", 0),
           {mm(423, 330, 247), mm(265, 330, 296), mm(314, 330, 456), mm(472, 330, 406)});

  Camera camera;
  camera.position = mm(278, 273, -800);
  camera.target = mm(278, 273, 0);
  camera.up = Vec3(0, 1, 0);
  camera.fovYDegrees = 2.0 * std::atan(0.0125 / 0.035) * 180.0 / M_PI;
  scene.camera = camera;
  return scene;
}

}  // namespace rt::app
