// validateScene on scenes built in code: the invariants every loader guarantees, with messages naming the
// origin.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/io/scene_loader.h"
#include "core/polygon.h"

namespace rt {
namespace {

Patch makePatch(const Polygon& vertices, int surface) {
  Patch p;
  p.vertices = vertices;
  p.normal = newellNormal(vertices).normalized();
  p.area = polygonArea(vertices);
  p.surface = surface;
  p.origin = {"built.json", 7, "/surfaces/0/polygons/0"};
  return p;
}

Scene validScene() {
  Scene s;
  s.sourceFile = "built.json";
  s.materials.push_back({"light", Rgb(0.2, 0.2, 0.2), Rgb(1, 1, 1)});
  s.surfaces.push_back({"square", 0});
  s.patches.push_back(makePatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, 0));
  return s;
}

std::string rejection(const Scene& s) {
  try {
    validateScene(s);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

TEST(SceneValidation, AcceptsAValidScene) {
  EXPECT_NO_THROW(validateScene(validScene()));
}

TEST(SceneValidation, RejectsBadMaterials) {
  Scene s = validScene();
  s.materials[0].reflectance = Rgb(0.2, 1.0, 0.2);
  EXPECT_NE(
      rejection(s).find("built.json: error: material 'light': reflectance [0.2, 1, 0.2] is outside [0,1)"),
      std::string::npos)
      << rejection(s);
  s = validScene();
  s.materials[0].reflectance[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(rejection(s).find("not a finite number"), std::string::npos) << rejection(s);
  s = validScene();
  s.materials[0].emission[2] = std::numeric_limits<double>::infinity();
  EXPECT_NE(rejection(s).find("emission [1, 1, inf] is not a finite number"), std::string::npos)
      << rejection(s);
  s = validScene();
  s.materials[0].emission[2] = -1;
  EXPECT_NE(rejection(s).find("negative"), std::string::npos) << rejection(s);
}

TEST(SceneValidation, ASceneWithoutLightIsValidButASolveRefusesIt) {
  Scene s = validScene();
  s.materials[0].emission = Rgb::Zero();
  EXPECT_NO_THROW(validateScene(s));
  try {
    requireLight(s);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("built.json: error: no light"), std::string::npos) << e.what();
  }
  s.patches.clear();
  EXPECT_NE(rejection(s).find("no polygons"), std::string::npos) << rejection(s);
}

TEST(SceneValidation, RejectsBadPatchesAtTheirOrigin) {
  const std::string origin = "built.json:7 at /surfaces/0/polygons/0: error: patch 0 (surface 'square')";
  Scene s = validScene();
  s.patches[0].vertices[1].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(rejection(s).find(origin + " has a coordinate that is not a finite number"), std::string::npos)
      << rejection(s);
  s = validScene();
  s.patches[0].vertices[2].z() = 0.1;
  EXPECT_NE(rejection(s).find(origin + " is not planar"), std::string::npos) << rejection(s);
  s = validScene();
  std::swap(s.patches[0].vertices[1], s.patches[0].vertices[2]);
  EXPECT_NE(rejection(s).find(origin), std::string::npos) << rejection(s);
  s = validScene();
  s.patches[0].normal = -s.patches[0].normal;
  EXPECT_NE(rejection(s).find("stored normal does not match"), std::string::npos) << rejection(s);
  s = validScene();
  s.patches[0].area = 2;
  EXPECT_NE(rejection(s).find("stored area 2 differs"), std::string::npos) << rejection(s);
  s = validScene();
  s.patches[0].surface = 3;
  EXPECT_NE(rejection(s).find("refers to surface 3"), std::string::npos) << rejection(s);
  s = validScene();
  s.surfaces[0].material = 5;
  EXPECT_NE(rejection(s).find("surface 'square' refers to material 5"), std::string::npos) << rejection(s);
}

TEST(SceneValidation, PatchWithoutOriginIsNamedByTheScenesFile) {
  Scene s = validScene();
  s.patches[0].origin = {};
  s.patches[0].area = 3;
  EXPECT_NE(rejection(s).find("built.json: error: patch 0"), std::string::npos) << rejection(s);
}

}  // namespace
}  // namespace rt
