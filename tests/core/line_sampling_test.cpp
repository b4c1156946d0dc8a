// The scrambled Sobol points of the quasi-Monte Carlo lines: the first 2^m points form a net in every
// projection the lines use (each elementary box holds exactly one point), whatever the seed; every point is
// uniform over the seeds (the shift makes the estimates unbiased); any index can start a run. And local lines
// drawn from them estimate a row of F with a smaller error than random ones at equal lines.
#include "core/formfactor/line_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "core/formfactor/local_lines.h"
#include "core/io/scene_loader.h"
#include "support/test_paths.h"

namespace rt {
namespace {

std::vector<std::vector<double>> points(int dimensions, int count, std::uint64_t seed,
                                        std::uint64_t from = 0) {
  ScrambledSobol sobol(dimensions, seed, 7);
  sobol.start(from);
  std::vector<std::vector<double>> out(static_cast<std::size_t>(count), std::vector<double>(dimensions));
  for (auto& p : out) sobol.next(p.data());
  return out;
}

TEST(ScrambledSobol, TheFirstPowerOfTwoPointsFillEveryIntervalOnceInEachDimension) {
  for (std::uint64_t seed : {1u, 2u, 99u}) {
    const auto p = points(5, 64, seed);
    for (int d = 0; d < 5; ++d) {
      std::vector<int> filled(64, 0);
      for (const auto& x : p) {
        ASSERT_GE(x[d], 0.0);
        ASSERT_LT(x[d], 1.0);
        ++filled[static_cast<std::size_t>(x[d] * 64)];
      }
      for (int k = 0; k < 64; ++k) EXPECT_EQ(filled[k], 1) << "seed " << seed << " dimension " << d;
    }
  }
}

TEST(ScrambledSobol, TheFirstTwoDimensionsAreANetInEveryBoxShape) {
  const auto p = points(5, 64, 3);
  for (int a = 0; a <= 6; ++a) {  // boxes 2^-a wide, 2^-(6-a) high
    const int columns = 1 << a, rows = 1 << (6 - a);
    std::vector<int> filled(64, 0);
    for (const auto& x : p) ++filled[static_cast<std::size_t>(int(x[0] * columns) * rows + int(x[1] * rows))];
    for (int k = 0; k < 64; ++k) EXPECT_EQ(filled[k], 1) << "boxes " << columns << " x " << rows;
  }
}

TEST(ScrambledSobol, EveryPointIsUniformOverTheSeeds) {
  for (int d = 0; d < 5; ++d) {
    double sum = 0, squares = 0;
    const int seeds = 4000;
    for (int s = 0; s < seeds; ++s) {
      const double x = points(5, 6, static_cast<std::uint64_t>(s + 1))[5][static_cast<std::size_t>(d)];
      sum += x;
      squares += x * x;
    }
    EXPECT_NEAR(sum / seeds, 0.5, 0.02) << "dimension " << d;
    EXPECT_NEAR(squares / seeds, 1.0 / 3.0, 0.02) << "dimension " << d;
  }
}

TEST(ScrambledSobol, StartingAtAnIndexContinuesTheSameSequence) {
  const auto whole = points(5, 40, 11);
  const auto tail = points(5, 15, 11, 25);
  for (int k = 0; k < 15; ++k)
    EXPECT_EQ(tail[static_cast<std::size_t>(k)], whole[static_cast<std::size_t>(25 + k)]);
  EXPECT_EQ(parseLineSampling("sobol"), LineSampling::Sobol);
  EXPECT_EQ(toString(LineSampling::Random), "random");
  EXPECT_FALSE(parseLineSampling("halton"));
}

// The Cornell box's light, unsubdivided: its row of F by quadrature against the counts of 4,096 local lines,
// random (jittered origins, random directions) and Sobol, over 12 seeds each.
TEST(ScrambledSobol, SobolLocalLinesEstimateTheLightsRowBetterThanRandomOnes) {
  const Mesh mesh = buildMesh(loadScene(test::sourcePath("scenes/cornell-box.json")), MeshOptions{});
  int light = -1;
  for (std::size_t i = 0; i < mesh.size(); ++i)
    if (mesh.emission.row(static_cast<Eigen::Index>(i)).maxCoeff() > 0) light = static_cast<int>(i);
  ASSERT_GE(light, 0);
  FormFactorStats stats;
  const FormFactorMatrix F = makeFormFactorMethod("quadrature")->compute(mesh, {}, noProgress(), stats);
  const RayScene scene(mesh);
  auto rmsError = [&](LineSampling sampling) {
    double squares = 0;
    const int lines = 4096, seeds = 12;
    for (int s = 1; s <= seeds; ++s) {
      std::vector<double> counts(mesh.size(), 0.0);
      for (const LocalLine& line : shootLocalLines(mesh, scene, light, lines, std::uint64_t(s), sampling))
        if (line.hit >= 0) counts[static_cast<std::size_t>(line.hit)] += 1.0 / lines;
      for (std::size_t j = 0; j < mesh.size(); ++j)
        squares += std::pow(counts[j] - F(light, static_cast<Eigen::Index>(j)), 2);
    }
    return std::sqrt(squares / seeds);
  };
  const double random = rmsError(LineSampling::Random), sobol = rmsError(LineSampling::Sobol);
  EXPECT_LT(sobol, 0.7 * random) << "random " << random << ", sobol " << sobol;
}

}  // namespace
}  // namespace rt
