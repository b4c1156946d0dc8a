// Benchmark, not a test (disabled; run with --gtest_also_run_disabled_tests): the path tracer's rays per
// second against Embree's raw rate on the same scene. The raw rate is rtcIntersect1 in a tight loop over rays
// made in advance, of the kind a path tracer casts (from uniform points of the closed Cornell box's elements,
// cosine-distributed about their normals), on the same triangles, threads and build quality; the path
// tracer's rate counts every ray it casts (bounces and shadow rays) over the wall time of rendering an image.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

#include "core/formfactor/sampling.h"
#include "core/io/scene_loader.h"
#include "core/pathtrace/path_tracer.h"
#include "support/test_paths.h"

namespace rt {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The tracing mesh's elements as one Embree triangle geometry (polygons fanned), as RayScene builds it.
RTCScene embreeScene(RTCDevice device, const Mesh& mesh) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  std::vector<unsigned> indices;
  for (const Element& element : mesh.elements)
    for (std::size_t k = 1; k + 1 < element.vertices.size(); ++k)
      indices.insert(indices.end(),
                     {static_cast<unsigned>(element.vertices[0]), static_cast<unsigned>(element.vertices[k]),
                      static_cast<unsigned>(element.vertices[k + 1])});
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) vertices[3 * v + c] = static_cast<float>(mesh.vertices[v](c));
  auto* triangles = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), indices.size() / 3));
  std::copy(indices.begin(), indices.end(), triangles);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  return scene;
}

TEST(PathTraceRateBenchmark, DISABLED_RaysPerSecondAgainstRawEmbree) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box-closed.json"));
  const PathTracer tracer(scene);
  const Mesh& mesh = tracer.tracing().mesh();
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());

  // Raw: 8 M rays made in advance, then rtcIntersect1 alone.
  constexpr std::size_t kRays = std::size_t(1) << 23;
  std::vector<RTCRayHit> rays(kRays);
  tbb::parallel_for(std::size_t(0), kRays, [&](std::size_t r) {
    PairRandom random(11, r, 0);
    const auto e =
        static_cast<std::size_t>(random.uniform() * static_cast<double>(mesh.size())) % mesh.size();
    const Polygon polygon = mesh.polygon(static_cast<int>(e));
    const PolygonSampler sampler(polygon.data(), static_cast<int>(polygon.size()));
    const Vec3 origin = sampler.point(random.uniform(), random.uniform());
    const Vec3 direction = cosineDirection(mesh.elements[e].normal, random.uniform(), random.uniform());
    RTCRayHit& ray = rays[r];
    ray.ray.org_x = static_cast<float>(origin.x());
    ray.ray.org_y = static_cast<float>(origin.y());
    ray.ray.org_z = static_cast<float>(origin.z());
    ray.ray.dir_x = static_cast<float>(direction.x());
    ray.ray.dir_y = static_cast<float>(direction.y());
    ray.ray.dir_z = static_cast<float>(direction.z());
    ray.ray.tnear = 1e-3f;
    ray.ray.tfar = 1e30f;
    ray.ray.mask = 0xffffffffu;
    ray.ray.flags = 0;
    ray.ray.time = 0;
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  });
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene embree = embreeScene(device, mesh);
  std::atomic<std::size_t> hits{0};
  auto start = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kRays, 4096), [&](const auto& range) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    std::size_t local = 0;
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      rtcIntersect1(embree, &context, &rays[r]);
      local += rays[r].hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
    hits += local;
  });
  const double rawSeconds = secondsSince(start);
  rtcReleaseScene(embree);
  rtcReleaseDevice(device);
  const double raw = static_cast<double>(kRays) / rawSeconds / threads;

  // The path tracer: a 256 x 256 image at 64 paths per pixel.
  PathTraceOptions options;
  options.samples = 64;
  start = std::chrono::steady_clock::now();
  tracer.render(scene.cameraOrDefault(), 256, 256, options);
  const double traceSeconds = secondsSince(start);
  const double traced = static_cast<double>(tracer.raysCast()) / traceSeconds / threads;

  std::printf("%zu elements, %u threads\n", mesh.size(), threads);
  std::printf("Embree rtcIntersect1, tight loop: %.3g rays in %.2f s, %.3g rays/s per core (%.1f %% hit)\n",
              static_cast<double>(kRays), rawSeconds, raw, 100.0 * static_cast<double>(hits) / kRays);
  std::printf("path tracer, 256 x 256 x 64 paths: %.3g rays in %.2f s, %.3g rays/s per core\n",
              static_cast<double>(tracer.raysCast()), traceSeconds, traced);
  std::printf("ratio: %.0f %%\n", 100 * traced / raw);
  EXPECT_GT(hits.load(), kRays * 99 / 100);  // a closed box: every ray hits
}

}  // namespace
}  // namespace rt
