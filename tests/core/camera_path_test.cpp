// Named cameras (JSON "cameras", OBJ "# camera NAME:" comments), --camera's name-or-text, and camera paths
// interpolated between named cameras.
#include <gtest/gtest.h>

#include "core/camera_path.h"
#include "core/io/scene_loader.h"

namespace rt {
namespace {

const char* kJson = R"({
  "camera": {"position": [0.5, 0.5, 3], "target": [0.5, 0.5, 0]},
  "cameras": {
    "front": {"position": [0.5, 0.5, 3], "target": [0.5, 0.5, 0], "fov_y_degrees": 50},
    "side": {"position": [3, 0.5, 0.5], "target": [0.5, 0.5, 0.5], "up": [0, 1, 0]}
  },
  "materials": [{"name": "light", "reflectance": 0, "emission": 1}, {"name": "white", "reflectance": 0.5}],
  "surfaces": [
    {"name": "floor", "material": "white", "polygons": [[[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]]},
    {"name": "lamp", "material": "light", "polygons": [[[0, 1, 0], [0, 1, 1], [1, 1, 1], [1, 1, 0]]]}
  ]
})";

const char* kObj = R"(# camera top: position 0.5 3 0.5 target 0.5 0 0.5 up 0 0 -1 fov_y_degrees 60
# camera low: position 0.5 0.2 3 target 0.5 0.2 0 up 0 1 0 fov_y_degrees 40
v 0 0 0
v 1 0 0
v 1 0 1
v 0 0 1
f 1 4 3 2
)";

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(NamedCameras, JsonScenesNameTheirCameras) {
  const Scene s = parseSceneJson(kJson, "room.json");
  ASSERT_EQ(s.cameras.size(), 2u);
  ASSERT_NE(s.findCamera("side"), nullptr);
  EXPECT_TRUE(s.findCamera("side")->position.isApprox(Vec3(3, 0.5, 0.5)));
  EXPECT_DOUBLE_EQ(s.findCamera("front")->fovYDegrees, 50);
  EXPECT_EQ(s.findCamera("back"), nullptr);
  EXPECT_EQ(cameraNameList(s), "front, side");
}

TEST(NamedCameras, AJsonCameraErrorNamesItsPath) {
  std::string text = kJson;
  // The side camera looks at its own position.
  text.replace(text.find("[3, 0.5, 0.5]"), 13, "[0.5, 0.5, 0.5]");
  EXPECT_NE(errorOf([&] { parseSceneJson(text, "room.json"); }).find("/cameras/side/target"),
            std::string::npos);
  text = kJson;
  text.replace(text.find("\"front\""), 7, "\"a b\"");
  EXPECT_NE(errorOf([&] { parseSceneJson(text, "room.json"); }).find("camera name 'a b'"), std::string::npos);
}

TEST(NamedCameras, ObjCommentsNameCameras) {
  const Scene s = parseSceneObj(kObj, "floor.obj", [](const std::string&) { return std::nullopt; });
  ASSERT_EQ(s.cameras.size(), 2u);
  EXPECT_EQ(s.cameras[0].name, "top");
  EXPECT_DOUBLE_EQ(s.findCamera("top")->fovYDegrees, 60);
  EXPECT_FALSE(s.camera.has_value()) << "named cameras leave the default camera alone";
  const std::string twice = std::string(kObj).replace(std::string(kObj).find("camera low"), 10, "camera top");
  const std::string error =
      errorOf([&] { parseSceneObj(twice, "floor.obj", [](const std::string&) { return std::nullopt; }); });
  EXPECT_NE(error.find("floor.obj:2"), std::string::npos) << error;
  EXPECT_NE(error.find("camera 'top' is named twice"), std::string::npos) << error;
}

TEST(NamedCameras, TheCameraOptionTakesANameOrAView) {
  const Scene s = parseSceneJson(kJson, "room.json");
  EXPECT_TRUE(cameraFromText(s, "side", {"--camera"}).position.isApprox(Vec3(3, 0.5, 0.5)));
  EXPECT_TRUE(cameraFromText(s, "position 1 2 3 target 0 0 0 up 0 1 0 fov_y_degrees 30", {"--camera"})
                  .position.isApprox(Vec3(1, 2, 3)));
  const std::string error = errorOf([&] { cameraFromText(s, "back", {"--camera"}); });
  EXPECT_NE(error.find("--camera"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown camera 'back' (the scene's cameras: front, side)"), std::string::npos)
      << error;
}

TEST(CameraPath, StartsAndEndsOnItsKeysAndPassesThroughTheMiddleOne) {
  Camera a{{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 40}, b{{10, 0, 0}, {0, 0, 0}, {0, 1, 0}, 60},
      c{{0, 0, -10}, {0, 0, 0}, {0, 1, 0}, 40};
  // b lies as far from a along the path as from c: with an odd number of frames the middle one is b.
  const auto path = interpolateCameraPath({a, b, c}, 21);
  ASSERT_EQ(path.size(), 21u);
  EXPECT_TRUE(path.front().position.isApprox(a.position));
  EXPECT_TRUE(path.back().position.isApprox(c.position));
  EXPECT_TRUE(path[10].position.isApprox(b.position, 1e-9));
  EXPECT_DOUBLE_EQ(path[10].fovYDegrees, 60);
  // Smooth: no frame jumps much further than the mean step.
  double longest = 0, total = 0;
  for (std::size_t f = 1; f < path.size(); ++f) {
    const double step = (path[f].position - path[f - 1].position).norm();
    longest = std::max(longest, step);
    total += step;
  }
  EXPECT_LT(longest, 1.6 * total / 20);
  EXPECT_EQ(interpolateCameraPath({a}, 3).size(), 3u);
  EXPECT_TRUE(interpolateCameraPath({}, 3).empty());
}

}  // namespace
}  // namespace rt
