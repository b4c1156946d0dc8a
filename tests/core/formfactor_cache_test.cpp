#include "core/formfactor/formfactor_cache.h"

#include <gtest/gtest.h>

#include "formfactor_scenes.h"
#include "support/test_paths.h"

namespace rt {
namespace {

TEST(FormFactorCache, MaterialOnlyChangesAreCacheHits) {
  Scene scene = test::closedBox(1, 2, 3);
  Mesh mesh = test::meshOf(scene, 2);
  FormFactorCache cache;
  bool hit = true;
  const auto first = cache.get("analytic", mesh, {}, noProgress(), &hit);
  EXPECT_FALSE(hit);
  // New emission and reflectance: geometry unchanged, F reused.
  scene.materials[1].emission = Rgb(5, 4, 3);
  scene.materials[0].reflectance = Rgb(0.1, 0.2, 0.3);
  refreshMaterials(mesh, scene);
  const auto second = cache.get("analytic", mesh, {}, noProgress(), &hit);
  EXPECT_TRUE(hit);
  EXPECT_EQ(first.get(), second.get());
  EXPECT_EQ(cache.hits(), 1u);
  // Different method, options or geometry: a miss.
  FormFactorOptions options;
  options.hemicubeResolution = 32;
  cache.get("hemicube", mesh, options, noProgress(), &hit);
  EXPECT_FALSE(hit);
  const Mesh finer = test::meshOf(scene, 3);
  cache.get("analytic", finer, {}, noProgress(), &hit);
  EXPECT_FALSE(hit);
  EXPECT_EQ(cache.misses(), 3u);
}

TEST(FormFactorCache, ASeedRecomputesOnlyTheMethodsThatDrawRandomNumbers) {
  const Mesh mesh = test::meshOf(test::closedBox(1, 2, 3), 2);
  FormFactorCache cache;
  FormFactorOptions first, second;
  first.hemicubeResolution = second.hemicubeResolution = 16;
  first.samples = second.samples = 64;
  second.seed = first.seed + 1;
  second.sampling = LineSampling::Sobol;
  bool hit = true;
  for (const char* method : {"hemicube", "quadrature", "nusselt"}) {
    const auto computed = cache.get(method, mesh, first, noProgress(), &hit);
    EXPECT_FALSE(hit) << method;
    const auto again = cache.get(method, mesh, second, noProgress(), &hit);
    EXPECT_TRUE(hit) << method << ": its matrix does not depend on the seed";
    EXPECT_EQ(computed.get(), again.get()) << method;
  }
  // Its knob still matters.
  second.hemicubeResolution = 32;
  cache.get("hemicube", mesh, second, noProgress(), &hit);
  EXPECT_FALSE(hit);
  // A stochastic method draws other lines with another seed.
  cache.get("montecarlo", mesh, first, noProgress(), &hit);
  EXPECT_FALSE(hit);
  second.sampling = first.sampling;
  cache.get("montecarlo", mesh, second, noProgress(), &hit);
  EXPECT_FALSE(hit);
}

TEST(FormFactorCache, DiskCacheSurvivesANewCache) {
  const std::string dir = test::scratchDir("formfactor_cache");
  const Mesh mesh = test::meshOf(test::closedBox(1, 1, 1), 2);
  bool hit = true;
  const auto computed = FormFactorCache(2, dir).get("analytic", mesh, {}, noProgress(), &hit);
  EXPECT_FALSE(hit);
  const auto loaded = FormFactorCache(2, dir).get("analytic", mesh, {}, noProgress(), &hit);
  EXPECT_TRUE(hit);
  EXPECT_EQ((computed->F - loaded->F).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace rt
