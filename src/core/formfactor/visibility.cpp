#include "core/formfactor/visibility.h"

#include <vector>

#include "core/formfactor/sampling.h"

namespace rt {

ConvexPolygon elementPolygon(const Mesh& mesh, int element) {
  const auto& vs = mesh.elements[static_cast<std::size_t>(element)].vertices;
  ConvexPolygon polygon;
  polygon.reserve(static_cast<int>(vs.size()));
  for (int index : vs) polygon.v[static_cast<std::size_t>(polygon.count++)] = mesh.vertices[index];
  return polygon;
}

PairVisibility::PairVisibility(const Mesh& mesh)
    : mesh_(mesh), shafts_(mesh), rays_(std::make_unique<RayScene>(mesh)) {}

double PairVisibility::fraction(int i, int j, int samples, std::uint64_t seed) const {
  const ConvexPolygon a = elementPolygon(mesh_, i), b = elementPolygon(mesh_, j);
  PairRandom random(seed ^ 0x5bd1e995ull, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j));
  // Stratum k on i with a randomly permuted stratum on j: a fixed shift would make each y a translated copy
  // of its x, and the N rays together worth about one independent sample.
  thread_local std::vector<int> strataOfJ;
  shuffledStrata(samples, random, strataOfJ);
  int visible = 0;
  for (int k = 0; k < samples; ++k) {
    const Vec2 s = jitteredSample(k, samples, random);
    const Vec2 t = jitteredSample(strataOfJ[static_cast<std::size_t>(k)], samples, random);
    const Vec3 x = pointOnPolygon(a.v.data(), a.count, s.x(), s.y());
    const Vec3 y = pointOnPolygon(b.v.data(), b.count, t.x(), t.y());
    visible += rays_->visible(x, y, i, j) ? 1 : 0;
  }
  return static_cast<double>(visible) / samples;
}

}  // namespace rt
