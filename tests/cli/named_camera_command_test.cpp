// --camera NAME: a camera the scene names gives the same picture as the same view typed out, and an unknown
// name is an input error naming --camera and the scene's cameras.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "support/test_paths.h"

namespace rt::test {
namespace {

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The solution's flat elements as PFM: no X server and no VTK needed, so this runs in every build.
TEST(NamedCameraCommand, ANamedCameraIsTheViewItNames) {
  const std::string dir = scratchDir("named-camera");
  std::string log;
  const std::string base = cliPath() + " render " + sourcePath("scenes/cornell-box.json") +
                           " --flat --max-edge 150 --width 120 --height 90";
  ASSERT_EQ(runCommand(base + " --camera back-high --output " + dir + "/named.pfm", &log), 0) << log;
  ASSERT_EQ(runCommand(base +
                           " --camera 'position 278 500 550 target 278 350 0 up 0 1 0 fov_y_degrees 80'"
                           " --output " +
                           dir + "/typed.pfm",
                       &log),
            0)
      << log;
  EXPECT_FALSE(bytesOf(dir + "/named.pfm").empty());
  EXPECT_EQ(bytesOf(dir + "/named.pfm"), bytesOf(dir + "/typed.pfm"));
}

TEST(NamedCameraCommand, AnUnknownNameListsTheScenesCameras) {
  std::string log;
  EXPECT_EQ(runCommand(cliPath() + " compare-pt " + sourcePath("scenes/cornell-box-closed.json") +
                           " --camera nowhere --output " + scratchDir("named-camera-unknown"),
                       &log),
            3)
      << log;
  EXPECT_NE(log.find("--camera: error: unknown camera 'nowhere' (the scene's cameras: "), std::string::npos)
      << log;
  EXPECT_NE(log.find("above"), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::test
