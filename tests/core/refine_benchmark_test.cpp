// The Cornell box numbers of docs/benchmarks.md (meshing section). Disabled by default because it takes a
// minute or two; run with
//   core_tests --gtest_also_run_disabled_tests --gtest_filter='RefineBenchmark.*'
#include <gtest/gtest.h>

#include <cstdio>

#include "core/io/scene_loader.h"
#include "core/refine/constrained_triangulation.h"
#include "core/refine/refine.h"
#include "support/test_paths.h"

namespace rt {
namespace {

void row(const char* label, const RefinedSolution& s, const RefinedSolution& reference) {
  const double n = static_cast<double>(s.stats.elements);
  const double work =
      s.stats.mode == RefineMode::Hierarchical ? static_cast<double>(s.stats.links) : s.stats.pairsComputed;
  std::printf("| %-36s | %6zu | %9.0f | %9.3g | %7.2f | %6.3f | %6.3f |\n", label, s.stats.elements, work,
              n * n, s.stats.seconds, relativeRmsError(s, reference), relativeRmsError(s, reference, true));
  std::fflush(stdout);
}

TEST(RefineBenchmark, DISABLED_CornellBox) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  RefineOptions ref;
  ref.mode = RefineMode::Uniform;
  ref.initialMaxEdge = 30;
  const RefinedSolution reference = solveRefined(scene, ref);
  std::printf("reference: %s\n", reference.stats.summary().c_str());
  std::printf("| %-36s | %6s | %9s | %9s | %7s | %6s | %6s |\n", "mesh", "n", "pairs/links", "n^2", "seconds",
              "error", "smooth");
  row("uniform, max edge 30 mm (reference)", reference, reference);
  for (double edge : {193.0, 100.0, 65.0, 45.0}) {
    RefineOptions o;
    o.mode = RefineMode::Uniform;
    o.initialMaxEdge = edge;
    char label[64];
    std::snprintf(label, sizeof label, "uniform, max edge %.0f mm", edge);
    row(label, solveRefined(scene, o), reference);
  }
  for (double tolerance : {0.5, 0.3, 0.2}) {
    RefineOptions o;
    o.mode = RefineMode::Adaptive;
    o.gradientTolerance = tolerance;
    o.maxElements = 4000;
    const RefinedSolution s = solveRefined(scene, o);
    char label[64];
    std::snprintf(label, sizeof label, "adaptive, tolerance %.2f", tolerance);
    row(label, s, reference);
    std::printf("   %s\n", s.stats.summary().c_str());
  }
  for (double edge : {193.0, 100.0}) {
    RefineOptions o;
    o.mode = RefineMode::Discontinuity;
    o.initialMaxEdge = edge;
    const RefinedSolution s = solveRefined(scene, o);
    char label[64];
    std::snprintf(label, sizeof label, "discontinuity (%s), %.0f mm", constrainedTriangulatorName().c_str(),
                  edge);
    row(label, s, reference);
    std::printf("   %s\n", s.stats.summary().c_str());
  }
  for (double tolerance : {0.01, 0.003, 0.001, 0.0003}) {
    RefineOptions o;
    o.mode = RefineMode::Hierarchical;
    o.linkTolerance = tolerance;
    o.minArea = 15.0 * 15.0;
    const RefinedSolution s = solveRefined(scene, o);
    char label[64];
    std::snprintf(label, sizeof label, "hierarchical BF, tolerance %g", tolerance);
    row(label, s, reference);
    std::printf("   %s\n", s.stats.summary().c_str());
  }
}

}  // namespace
}  // namespace rt
