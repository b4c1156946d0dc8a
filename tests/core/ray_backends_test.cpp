// The portable ray back end (the core's own BVH, used where the build has no Embree, as in the browser)
// against Embree on the same rays: every query of RayScene gives the same element, side and distance, apart
// from rays that pass within float rounding of a triangle's edge, where the two may pick either neighbour.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/formfactor/ray_scene.h"
#include "core/formfactor/sampling.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "support/test_paths.h"

namespace rt {
namespace {

struct Agreement {
  int rays = 0, hits = 0, differ = 0;
};

Vec3 centroid(const Mesh& mesh, int e) {
  Vec3 c = Vec3::Zero();
  for (int v : mesh.elements[std::size_t(e)].vertices) c += mesh.vertices[std::size_t(v)];
  return c / double(mesh.elements[std::size_t(e)].vertices.size());
}

// Rays from random points of the scene's box in uniform directions, and segments between element
// centroids: both back ends answer each of the four queries.
Agreement compare(const std::string& file, double maxEdge) {
  const Scene scene = loadScene(test::sourcePath(file));
  MeshOptions options = defaultMeshOptions(scene);
  if (maxEdge > 0) {
    options.mode = MeshOptions::Mode::MaxEdge;
    options.maxEdge = maxEdge;
  }
  const Mesh mesh = buildMesh(scene, options);
  const RayScene embree(mesh, RayBackend::embree);
  const RayScene portable(mesh, RayBackend::portable);
  EXPECT_EQ(embree.backend(), RayBackend::embree);
  EXPECT_EQ(portable.backend(), RayBackend::portable);
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  PairRandom random(11, 12, 13);
  Agreement out;
  const int n = static_cast<int>(mesh.size());
  for (int k = 0; k < 4000; ++k) {
    const Vec3 origin =
        box.min() +
        (box.max() - box.min()).cwiseProduct(Vec3(random.uniform(), random.uniform(), random.uniform()));
    const double z = 2 * random.uniform() - 1, phi = 2 * std::numbers::pi * random.uniform();
    const Vec3 direction(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    for (const bool after : {false, true}) {
      const RayHit a =
          after ? embree.firstHitAfter(origin, direction, 1e-6) : embree.firstHit(origin, direction, -1);
      const RayHit b =
          after ? portable.firstHitAfter(origin, direction, 1e-6) : portable.firstHit(origin, direction, -1);
      ++out.rays;
      if (a.element >= 0) ++out.hits;
      const bool same = a.element == b.element && a.frontSide == b.frontSide &&
                        (a.element < 0 || std::abs(a.distance - b.distance) <= 1e-5 * embree.sceneSize());
      if (!same) ++out.differ;
    }
    const int i = static_cast<int>(random.uniform() * n) % n, j = static_cast<int>(random.uniform() * n) % n;
    if (i == j) continue;
    const Vec3 from = centroid(mesh, i), to = centroid(mesh, j);
    out.rays += 2;
    if (embree.visible(from, to, i, j) != portable.visible(from, to, i, j)) ++out.differ;
    if (embree.visibleAfter(origin, to, 1e-6, j) != portable.visibleAfter(origin, to, 1e-6, j)) ++out.differ;
  }
  return out;
}

TEST(RayBackends, PortableBvhGivesEmbreesHitsInTheCornellBox) {
  if (!rayBackendAvailable(RayBackend::embree)) GTEST_SKIP() << "built without Embree";
  const Agreement a = compare("scenes/cornell-box.json", 0);
  EXPECT_GT(a.hits, a.rays / 4);
  // Edge cases only: a ray through the shared edge of two triangles, found by one back end on either side.
  EXPECT_LE(a.differ, a.rays / 1000) << a.differ << " of " << a.rays;
}

TEST(RayBackends, PortableBvhGivesEmbreesHitsInAFineOccludedRoom) {
  if (!rayBackendAvailable(RayBackend::embree)) GTEST_SKIP() << "built without Embree";
  const Agreement a = compare("scenes/grid-room-20.json", 0);
  EXPECT_GT(a.hits, a.rays / 4);
  EXPECT_LE(a.differ, a.rays / 1000) << a.differ << " of " << a.rays;
}

TEST(RayBackends, AutomaticIsEmbreeWhereBuilt) {
  const Scene scene = loadScene(test::sourcePath("scenes/parallel-squares.json"));
  const Mesh mesh = buildMesh(scene, defaultMeshOptions(scene));
  const RayScene rays(mesh);
  EXPECT_EQ(rays.backend(),
            rayBackendAvailable(RayBackend::embree) ? RayBackend::embree : RayBackend::portable);
}

}  // namespace
}  // namespace rt
