// The scene model: planar convex one-sided polygons (patches) grouped into named surfaces that share a
// material. Units: lengths in the scene's unit (metres unless the file says otherwise), emission and
// radiosity in W/m^2, reflectance in [0,1) per RGB channel. See docs/scene-format.md and docs/conventions.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/vec.h"

namespace rt {

struct Material {
  std::string name;
  Rgb reflectance = Rgb::Zero();  // rho, each channel in [0,1)
  Rgb emission = Rgb::Zero();     // E >= 0, W/m^2 (radiant exitance of the emitter)
  bool isEmitter() const { return (emission > 0.0).any(); }
};

struct Surface {
  std::string name;   // e.g. "left_wall"; several patches may share a surface
  int material = -1;  // index into Scene::materials
};

struct Patch {
  Polygon vertices;  // planar, convex, counter-clockwise seen from the front (the side it faces)
  Vec3 normal;       // unit normal of the front side (right-hand rule of the vertex order)
  double area = 0.0;
  int surface = -1;       // index into Scene::surfaces
  SourceLocation origin;  // where it was defined, for messages
};

struct Camera {
  Vec3 position{0, 0, 1};
  Vec3 target{0, 0, 0};  // a point the camera looks at
  Vec3 up{0, 1, 0};
  double fovYDegrees = 40.0;  // vertical field of view
};

// A view a scene names, so that a command (--camera NAME), a lesson step (camera: NAME) or a camera path can
// ask for it.
struct NamedCamera {
  std::string name;
  Camera camera;
};

struct Scene {
  std::string name;
  std::string sourceFile;
  std::string unit = "m";  // informative: the unit of the coordinates ("m", "mm", ...)
  std::vector<Material> materials;
  std::vector<Surface> surfaces;
  std::vector<Patch> patches;
  std::optional<Camera> camera;
  // JSON "cameras" (in name order: a JSON object has none) and OBJ "# camera NAME: ..." comments (in file
  // order)
  std::vector<NamedCamera> cameras;
  std::vector<std::string> warnings;  // e.g. non-planar quads that were split, each naming file and line

  const Material& materialOf(const Patch& p) const { return materials[surfaces[p.surface].material]; }
  const Material& materialOfPatch(int patchIndex) const { return materialOf(patches[patchIndex]); }
  bool hasEmitter() const;
  double totalArea() const;
  // Axis-aligned bounds of all patch vertices.
  Eigen::AlignedBox3d bounds() const;
  // A camera looking at the whole scene when the file gives none.
  Camera cameraOrDefault() const;
  // The camera called `name`, or null.
  const Camera* findCamera(const std::string& name) const;
};

}  // namespace rt
