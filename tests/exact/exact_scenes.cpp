#include "exact/exact_scenes.h"

#include <algorithm>

#include "core/polygon.h"

namespace rt::exact::test {

Scene sceneFromPolygons(const std::vector<Polygon>& polygons) {
  Scene scene;
  scene.name = "test";
  Material grey;
  grey.name = "grey";
  grey.reflectance = Rgb::Constant(0.5);
  scene.materials.push_back(grey);
  scene.surfaces.push_back({"surface", 0});
  for (const Polygon& polygon : polygons) {
    Patch patch;
    patch.vertices = polygon;
    patch.normal = newellNormal(polygon).normalized();
    patch.area = polygonArea(polygon);
    patch.surface = 0;
    scene.patches.push_back(patch);
  }
  return scene;
}

Mesh meshFromPolygons(const std::vector<Polygon>& polygons, int subdivide) {
  MeshOptions options;
  if (subdivide > 1) {
    options.mode = MeshOptions::Mode::Count;
    options.count = subdivide;
  }
  return buildMesh(sceneFromPolygons(polygons), options);
}

Polygon axisRectangle(int axis, double at, const Vec3& lo, const Vec3& hi, bool facePositive) {
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  auto point = [&](double u, double v) {
    Vec3 p;
    p[axis] = at;
    p[a] = u;
    p[b] = v;
    return p;
  };
  // (a, b, axis) is right-handed, so a -> b counter-clockwise faces +axis.
  Polygon rect{point(lo[a], lo[b]), point(hi[a], lo[b]), point(hi[a], hi[b]), point(lo[a], hi[b])};
  if (!facePositive) std::reverse(rect.begin(), rect.end());
  return rect;
}

std::vector<Polygon> boxFaces(const Vec3& lo, const Vec3& hi, bool withBottom) {
  std::vector<Polygon> faces;
  for (int axis = 0; axis < 3; ++axis) {
    if (axis != 1 || withBottom) faces.push_back(axisRectangle(axis, lo[axis], lo, hi, false));
    faces.push_back(axisRectangle(axis, hi[axis], lo, hi, true));
  }
  return faces;
}

std::vector<Polygon> roomFaces(const Vec3& lo, const Vec3& hi) {
  std::vector<Polygon> faces;
  for (int axis = 0; axis < 3; ++axis) {
    faces.push_back(axisRectangle(axis, lo[axis], lo, hi, true));
    faces.push_back(axisRectangle(axis, hi[axis], lo, hi, false));
  }
  return faces;
}

}  // namespace rt::exact::test
