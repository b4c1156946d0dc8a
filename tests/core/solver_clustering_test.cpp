// Hierarchical radiosity with clustering on small versions of the course's museum and factory: the solution
// agrees with a dense solve within its own error estimate, the links and bytes grow like n, and a closed box
// of uniform reflectance and emission gives E / (1 - rho).
#include "core/solvers/clustering_solver.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/solvers/cluster_directions.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/solver.h"
#include "support/test_paths.h"

namespace rt {
namespace {

// One element per polygon, as `radiosity solve` keeps these scenes.
Mesh polygonsOf(const std::string& path) {
  MeshOptions options;
  options.mode = MeshOptions::Mode::None;
  return buildMesh(loadScene(path), options);
}

struct ClusteredRun {
  RgbField B, estimate;
  SolverStatus status = SolverStatus::InvalidInput;
  double reported = 0;  // the area-weighted relative RMS estimate
  long links = 0, nodes = 0;
  long long bytes = 0;
};

ClusteredRun solveClustered(const RadiositySystem& system, double clusterTolerance = 0) {
  SolverOptions o;
  o.clusterTolerance = clusterTolerance;
  o.recordHistory = false;
  ClusteredRun run;
  IterationRecord last;
  run.status = hierarchicalClustering(
      system, run.B, o, [&](IterationRecord r) { last = std::move(r); }, &run.estimate);
  run.reported = last.standardError;
  run.links = last.links;
  run.nodes = last.nodes;
  run.bytes = last.memoryBytes;
  return run;
}

// sqrt(sum_i A_i |B_i - R_i|^2) / sqrt(sum_i A_i |R_i|^2), all channels: the error the benchmarks report.
double areaRelativeRms(const RgbField& B, const RgbField& reference, const Eigen::VectorXd& areas) {
  return std::sqrt((B - reference).rowwise().squaredNorm().dot(areas) /
                   reference.rowwise().squaredNorm().dot(areas));
}

class ClusteringAgainstDense : public ::testing::TestWithParam<std::string> {};

TEST_P(ClusteringAgainstDense, AgreesWithinItsErrorEstimate) {
  const Mesh mesh = polygonsOf(test::sourcePath("tests/data/large-scenes/" + GetParam() + "-1k.obj"));
  ASSERT_GT(mesh.size(), 900u);
  // The dense reference: exact unoccluded form factors times 64-ray visibility, solved by LU.
  FormFactorOptions options;
  options.samples = 64;
  FormFactorStats stats;
  const FormFactorMatrix F =
      makeFormFactorMethod("analytic-visibility")->compute(mesh, options, noProgress(), stats);
  RgbField reference;
  ASSERT_EQ(directSolve(RadiositySystem::fromMesh(mesh, F), reference, {}), SolverStatus::Success);

  const ClusteredRun run = solveClustered(RadiositySystem::fromGeometry(mesh));
  ASSERT_EQ(run.status, SolverStatus::Success);
  const double error = areaRelativeRms(run.B, reference, mesh.areas());
  std::printf("%s: %ld links, error %.3g, estimate %.3g\n", GetParam().c_str(), run.links, error,
              run.reported);
  EXPECT_GT(run.reported, 0.0);
  EXPECT_LE(error, run.reported);
  // The estimate is an estimate, not a blanket: within a few times the error.
  EXPECT_LE(run.reported, 6.0 * error);
  // The per-element estimate in the same norm is the reported one.
  EXPECT_NEAR(std::sqrt(run.estimate.rowwise().squaredNorm().dot(mesh.areas()) /
                        run.B.rowwise().squaredNorm().dot(mesh.areas())),
              run.reported, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(LargeScenes, ClusteringAgainstDense, ::testing::Values("museum", "factory"));

class ClusteringMemory : public ::testing::TestWithParam<std::string> {};

// Links and bytes (counted from the containers) at n, 2n and 4n elements: about linear, never n^2. From
// 2k elements on, each doubling of n must at most multiply them by 2.4, and 4n at most by 5.5 (n^2 would
// give 4 and 16); and the bytes stay below 8 kB per element.
TEST_P(ClusteringMemory, LinksAndBytesGrowLikeN) {
  if (test::runCommand("python3 -c 'import math'") != 0) GTEST_SKIP() << "python3 generates the scenes";
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       ("rt-clustering-" + GetParam() + "-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  long links[3] = {};
  long long bytes[3] = {};
  std::size_t elements[3] = {};
  for (int k = 0; k < 3; ++k) {
    const std::string obj = (folder / (GetParam() + std::to_string(k) + ".obj")).string();
    ASSERT_EQ(test::runCommand("python3 " + test::sourcePath("scenes/tools/make_large_scenes.py") + " " +
                               GetParam() + " " + std::to_string(2000 << k) + " " + obj),
              0);
    const Mesh mesh = polygonsOf(obj);
    const ClusteredRun run = solveClustered(RadiositySystem::fromGeometry(mesh));
    ASSERT_EQ(run.status, SolverStatus::Success);
    links[k] = run.links;
    bytes[k] = run.bytes;
    elements[k] = mesh.size();
    EXPECT_EQ(run.nodes, static_cast<long>(2 * mesh.size() - 1));
    EXPECT_LT(double(run.bytes), 8000.0 * double(mesh.size()));
    std::printf("%s: %zu elements, %ld links, %lld bytes\n", GetParam().c_str(), mesh.size(), run.links,
                run.bytes);
  }
  std::filesystem::remove_all(folder);
  EXPECT_NEAR(double(elements[2]) / double(elements[0]), 4.0, 0.2);
  for (int k = 1; k < 3; ++k) {
    EXPECT_LE(double(links[k]) / double(links[k - 1]), 2.4);
    EXPECT_LE(double(bytes[k]) / double(bytes[k - 1]), 2.4);
  }
  EXPECT_LE(double(links[2]) / double(links[0]), 5.5);
  EXPECT_LE(double(bytes[2]) / double(bytes[0]), 5.5);
}

INSTANTIATE_TEST_SUITE_P(LargeScenes, ClusteringMemory, ::testing::Values("museum", "factory"));

// The furnace: a closed cube, every element with the same reflectance and emission, has B = E / (1 - rho)
// whatever the form factors, so what the links miss shows as a departure from it.
TEST(ClusteringFurnace, ClosedBoxGivesEOverOneMinusRhoWithinTheEstimate) {
  MeshOptions options;
  options.mode = MeshOptions::Mode::Count;
  options.count = 8;  // 384 elements
  const Mesh mesh = buildMesh(loadScene(test::sourcePath("scenes/furnace-cube.json")), options);
  for (const double rho : {0.5, 0.9}) {
    RadiositySystem system = RadiositySystem::fromGeometry(mesh);
    system.reflectance.setConstant(rho);
    system.emission.setConstant(1.0);
    const ClusteredRun run = solveClustered(system);
    ASSERT_EQ(run.status, SolverStatus::Success);
    const RgbField expected = RgbField::Constant(mesh.size(), 3, 1.0 / (1.0 - rho));
    const double error = areaRelativeRms(run.B, expected, mesh.areas());
    std::printf("rho %.1f: error %.3g, estimate %.3g\n", rho, error, run.reported);
    EXPECT_LE(error, run.reported) << "rho " << rho;
    // Energy: the area-weighted mean radiosity is the furnace's to within the estimate too.
    const double mean = run.B.col(0).dot(mesh.areas()) / mesh.areas().sum();
    EXPECT_NEAR(mean, 1.0 / (1.0 - rho), run.reported / (1.0 - rho)) << "rho " << rho;
  }
}

// A sloping emitter over a floor, nothing else: the floor's light comes along links from clusters of the
// slope's elements, so it is right only if a cluster of tilted elements radiates their cosine. With the
// six axis bins alone a 45-degree slope sent 0.5 instead of 0.71 of its intensity straight down, and the
// floor came out about 20 % darker than the dense solve (the factory's floor under its sawtooth roof: 6 %).
TEST(ClusteringDirections, FloorUnderASlopingEmitterAgreesWithADenseSolve) {
  const Scene scene = parseSceneJson(R"({
    "materials": [{"name": "light", "reflectance": [0, 0, 0], "emission": [1, 1, 1]},
                  {"name": "floor", "reflectance": [0.5, 0.5, 0.5]}],
    "surfaces": [
      {"name": "slope", "material": "light", "polygons": [[[3, 8, 3], [7, 12, 3], [7, 12, 7], [3, 8, 7]]]},
      {"name": "floor", "material": "floor", "polygons": [[[0, 0, 0], [0, 0, 10], [10, 0, 10], [10, 0, 0]]]}]
  })");
  MeshOptions options;
  options.mode = MeshOptions::Mode::MaxEdge;
  options.maxEdge = 0.5;
  const Mesh mesh = buildMesh(scene, options);
  // The reference: exact form factors (nothing occludes anything here), solved by LU.
  FormFactorStats stats;
  const FormFactorMatrix F = makeFormFactorMethod("analytic")->compute(mesh, {}, noProgress(), stats);
  RgbField reference;
  ASSERT_EQ(directSolve(RadiositySystem::fromMesh(mesh, F), reference, {}), SolverStatus::Success);

  const ClusteredRun run = solveClustered(RadiositySystem::fromGeometry(mesh));
  ASSERT_EQ(run.status, SolverStatus::Success);
  double floorArea = 0, got = 0, expected = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e)
    if (mesh.elements[e].normal.y() > 0.99) {
      const double a = mesh.elements[e].area;
      floorArea += a;
      got += a * run.B(Eigen::Index(e), 0);
      expected += a * reference(Eigen::Index(e), 0);
    }
  ASSERT_NEAR(floorArea, 100.0, 1e-9);
  std::printf("floor mean: clustered %.5f, dense %.5f (%ld links, estimate %.3g)\n", got / floorArea,
              expected / floorArea, run.links, run.reported);
  EXPECT_NEAR(got / expected, 1.0, 0.01);
  EXPECT_LE(areaRelativeRms(run.B, reference, mesh.areas()), run.reported);
}

// The model itself: a class of tilted elements radiates B A cos / pi in every direction, and an element
// of that class receives the cosine-weighted irradiance.
TEST(ClusteringDirections, ATiltedClassRadiatesAndReceivesItsCosine) {
  const Scene scene = parseSceneJson(R"({
    "materials": [{"name": "grey", "reflectance": [0.5, 0.5, 0.5]}],
    "surfaces": [{"name": "slope", "material": "grey",
                  "polygons": [[[0, 0, 0], [4, 3, 0], [4, 3, 2], [0, 0, 2]]]}]
  })");
  MeshOptions options;
  options.mode = MeshOptions::Mode::Count;
  options.count = 2;
  const Mesh mesh = buildMesh(scene, options);
  const ClusterDirections directions(mesh);
  ASSERT_EQ(directions.classes(), 7);
  const Vec3 n = mesh.elements[0].normal.normalized();
  std::vector<double> D(3 * 7, 0.0);
  const double power[3] = {1, 2, 3};
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    EXPECT_EQ(directions.classOf(int(e)), 6);
    directions.spread(int(e), power, D.data());
  }
  for (const Vec3& w :
       {n, Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(-0.6, 0.8, 0), Vec3(0.3, -0.2, 0.9).normalized()}) {
    double sent[3];
    directions.radiate(D.data(), w, sent);
    EXPECT_NEAR(sent[1], 2.0 * 4.0 * std::max(0.0, n.dot(w)), 1e-12) << w.transpose();
    std::vector<double> bins(3 * 7, 0.0);
    directions.receive(power, w, bins.data());
    double got[3];
    directions.pick(0, bins.data(), got);
    EXPECT_NEAR(got[2], 3.0 * std::max(0.0, n.dot(w)), 1e-12) << w.transpose();
  }
}

// A tilted normal with less than 1 % of the scene's area gets no class: it is spread over the axis classes
// with weights summing to 1, so its power over all directions is kept.
TEST(ClusteringDirections, ASmallTiltedPatchIsSpreadOverTheAxes) {
  const Scene scene = parseSceneJson(R"({
    "materials": [{"name": "grey", "reflectance": [0.5, 0.5, 0.5]}],
    "surfaces": [
      {"name": "floor", "material": "grey", "polygons": [[[0, 0, 0], [0, 0, 10], [10, 0, 10], [10, 0, 0]]]},
      {"name": "chip", "material": "grey", "polygons": [[[0, 1, 0], [0.3, 1.4, 0], [0.3, 1.4, 0.2]]]}]
  })");
  MeshOptions options;
  options.mode = MeshOptions::Mode::None;
  const Mesh mesh = buildMesh(scene, options);
  const ClusterDirections directions(mesh);
  ASSERT_EQ(directions.classes(), 6);
  EXPECT_EQ(directions.classOf(0), 2);  // +y
  EXPECT_EQ(directions.classOf(1), -1);
  std::vector<double> D(3 * 6, 0.0);
  const double power[3] = {1, 1, 1};
  directions.spread(1, power, D.data());
  double total = 0;
  for (int c = 0; c < 6; ++c) total += D[std::size_t(3 * c)];
  EXPECT_NEAR(total, 1.0, 1e-12);
}

}  // namespace
}  // namespace rt
