#include "core/formfactor/local_lines.h"

#include <memory>

#include "core/formfactor/sampling.h"
#include "core/formfactor/visibility.h"

namespace rt {

std::vector<LocalLine> shootLocalLines(const Mesh& mesh, const RayScene& scene, int i, int count,
                                       std::uint64_t seed, LineSampling sampling) {
  std::vector<LocalLine> lines;
  if (i < 0 || i >= static_cast<int>(mesh.size()) || count < 1) return lines;
  lines.reserve(static_cast<std::size_t>(count));
  const ConvexPolygon a = elementPolygon(mesh, i);
  const Vec3& normal = mesh.elements[static_cast<std::size_t>(i)].normal;
  PairRandom random(seed, static_cast<std::uint64_t>(i), 0x6d6f6e7465ull);
  // Off the element's plane by far less than any feature, so that the line cannot start behind it.
  const double lift = 1e-9 * scene.sceneSize();
  std::unique_ptr<ScrambledSobol> sobol;
  if (sampling == LineSampling::Sobol) {
    sobol = std::make_unique<ScrambledSobol>(4, seed, static_cast<std::uint64_t>(i));
    sobol->start(0);
  }
  for (int k = 0; k < count; ++k) {
    double u[4];
    if (sobol) {
      sobol->next(u);
    } else {
      const Vec2 s = jitteredSample(k, count, random);
      u[0] = s.x();
      u[1] = s.y();
      // The direction's second number first: the order the earlier code's arguments were evaluated in, so
      // that a seed gives the lines it always gave.
      u[3] = random.uniform();
      u[2] = random.uniform();
    }
    LocalLine line;
    line.origin = pointOnPolygon(a.v.data(), a.count, u[0], u[1]) + lift * normal;
    line.direction = cosineDirection(normal, u[2], u[3]);
    const RayHit hit = scene.firstHit(line.origin, line.direction, i);
    line.struck = hit.element;
    line.distance = hit.element >= 0 ? hit.distance : 0.0;
    line.hit = hit.element >= 0 && hit.frontSide ? hit.element : -1;
    lines.push_back(line);
  }
  return lines;
}

}  // namespace rt
