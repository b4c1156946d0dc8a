#include "core/formfactor/local_lines.h"

#include "core/formfactor/sampling.h"
#include "core/formfactor/visibility.h"

namespace rt {

std::vector<LocalLine> shootLocalLines(const Mesh& mesh, const RayScene& scene, int i, int count,
                                       std::uint64_t seed) {
  std::vector<LocalLine> lines;
  if (i < 0 || i >= static_cast<int>(mesh.size()) || count < 1) return lines;
  lines.reserve(static_cast<std::size_t>(count));
  const ElementPolygon a(mesh, i);
  const Vec3& normal = mesh.elements[static_cast<std::size_t>(i)].normal;
  PairRandom random(seed, static_cast<std::uint64_t>(i), 0x6d6f6e7465ull);
  // Off the element's plane by far less than any feature, so that the line cannot start behind it.
  const double lift = 1e-9 * scene.sceneSize();
  for (int k = 0; k < count; ++k) {
    const Vec2 s = jitteredSample(k, count, random);
    LocalLine line;
    line.origin = pointOnPolygon(a.v.data(), a.count, s.x(), s.y()) + lift * normal;
    line.direction = cosineDirection(normal, random.uniform(), random.uniform());
    const RayHit hit = scene.firstHit(line.origin, line.direction, i);
    line.struck = hit.element;
    line.distance = hit.element >= 0 ? hit.distance : 0.0;
    line.hit = hit.element >= 0 && hit.frontSide ? hit.element : -1;
    lines.push_back(line);
  }
  return lines;
}

}  // namespace rt
