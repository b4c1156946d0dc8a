#include "core/camera_path.h"

#include <algorithm>
#include <cmath>

#include "core/io/scene_loader.h"

namespace rt {

bool isCameraName(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_' || c == '.';
  });
}

std::string cameraNameList(const Scene& scene) {
  std::string out;
  for (const NamedCamera& c : scene.cameras) out += (out.empty() ? "" : ", ") + c.name;
  return out.empty() ? "none" : out;
}

const Camera& namedCamera(const Scene& scene, const std::string& name, const SourceLocation& where) {
  if (const Camera* camera = scene.findCamera(name)) return *camera;
  throw InputError(where,
                   "unknown camera '" + name + "' (the scene's cameras: " + cameraNameList(scene) + ")");
}

Camera cameraFromText(const Scene& scene, const std::string& text, const SourceLocation& where) {
  std::string trimmed = text;
  trimmed.erase(0, trimmed.find_first_not_of(" \t"));
  trimmed.erase(trimmed.find_last_not_of(" \t") + 1);
  if (isCameraName(trimmed) && trimmed != "position") return namedCamera(scene, trimmed, where);
  return parseCameraText(text, where);
}

namespace {

// Catmull-Rom through p1..p2 at t in [0, 1], p0 and p3 the neighbours (centripetal spacing is not needed:
// the keys are spaced by distance already).
Vec3 catmullRom(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return 0.5 * ((2 * p1) + (-p0 + p2) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 +
                (-p0 + 3 * p1 - 3 * p2 + p3) * t3);
}

}  // namespace

std::vector<Camera> interpolateCameraPath(const std::vector<Camera>& keys, int frames) {
  std::vector<Camera> out;
  if (keys.empty() || frames < 1) return out;
  if (keys.size() == 1) return std::vector<Camera>(static_cast<std::size_t>(frames), keys.front());
  // Where each key sits along the path: the eye's distance travelled (keys at one place count as one step,
  // so that a turn on the spot still takes frames).
  std::vector<double> at{0.0};
  double scale = 0;
  for (std::size_t k = 1; k < keys.size(); ++k) scale += (keys[k].position - keys[k - 1].position).norm();
  const double floor = scale > 0 ? 0.05 * scale / static_cast<double>(keys.size() - 1) : 1.0;
  for (std::size_t k = 1; k < keys.size(); ++k)
    at.push_back(at.back() + std::max((keys[k].position - keys[k - 1].position).norm(), floor));
  const auto n = keys.size();
  for (int f = 0; f < frames; ++f) {
    const double s = frames == 1 ? 0.0 : at.back() * f / (frames - 1);
    std::size_t k = 0;
    while (k + 2 < n && s > at[k + 1]) ++k;
    const double t = std::clamp((s - at[k]) / (at[k + 1] - at[k]), 0.0, 1.0);
    const Camera& a = keys[k];
    const Camera& b = keys[k + 1];
    const Camera& before = keys[k > 0 ? k - 1 : k];
    const Camera& after = keys[std::min(k + 2, n - 1)];
    Camera c;
    c.position = catmullRom(before.position, a.position, b.position, after.position, t);
    c.target = catmullRom(before.target, a.target, b.target, after.target, t);
    c.up = catmullRom(before.up, a.up, b.up, after.up, t);
    if (c.up.norm() > 0) c.up.normalize();
    c.fovYDegrees = (1 - t) * a.fovYDegrees + t * b.fovYDegrees;
    out.push_back(c);
  }
  return out;
}

}  // namespace rt
