// The lesson on meshing: what its text says about the numbers and figures of its steps, checked on those
// steps (same scene, same parameters).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/io/rgb_image.h"
#include "core/refine/refine.h"
#include "lesson/step_runner.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

using Ran = test::RanStep;

Ran run(const std::string& figure, const std::function<void(StepParameters&)>& change = {}) {
  return test::runStepWithFigure("meshing", figure, change);
}

// The split rule of equation (split): tau = tolerance x the mean luminance of the elements that emit nothing,
// as the step reports it; the adaptive mesh grew from its start and has the T-vertices the text counts.
TEST(MeshingLesson, TheAdaptiveThresholdIsTheToleranceTimesTheMeanLuminance) {
  const Ran r = run("adaptive");
  ASSERT_TRUE(r.result.refined);
  const RefinedSolution& s = *r.result.refined;
  // The mean the split rule scales (core/refine: elementsToSplit calls the same function), between the
  // darkest and the brightest reflecting element.
  EXPECT_DOUBLE_EQ(r["luminance.mean"], meanReflectingLuminance(s.mesh, s.B));
  double lo = 1e300, hi = 0;
  for (std::size_t e = 0; e < s.mesh.size(); ++e)
    if ((s.mesh.emission.row(static_cast<Eigen::Index>(e)).array() <= 0).all()) {
      lo = std::min(lo, luminance(s.B.row(static_cast<Eigen::Index>(e))));
      hi = std::max(hi, luminance(s.B.row(static_cast<Eigen::Index>(e))));
    }
  EXPECT_GT(r["luminance.mean"], lo);
  EXPECT_LT(r["luminance.mean"], hi);
  EXPECT_NEAR(r["split-threshold"], r["refine-tolerance"] * r["luminance.mean"], 1e-12);
  EXPECT_GT(r["elements"], r["elements.initial"]) << "elements split";
  EXPECT_GT(r["passes"], 1);
  EXPECT_GT(r["t-vertices"], 0) << "split elements meet unsplit ones";
  EXPECT_EQ(r["t-vertices"], static_cast<double>(s.tVertices.size()));
}

// "Lower it with the control and more elements split."
TEST(MeshingLesson, ALowerToleranceSplitsMore) {
  const Ran r = run("adaptive");
  const Ran lower =
      run("adaptive", [&](StepParameters& p) { p.refineTolerance = 0.5 * r["refine-tolerance"]; });
  EXPECT_GT(lower["elements"], r["elements"]);
}

// The critical lines: counted by kind (extremal + interior, VE + EV add up to all), and drawn by the
// discontinuity view from the solution the step keeps; the discontinuity mesh has more elements than the
// plain mesh it starts from.
TEST(MeshingLesson, TheDiscontinuityMeshCountsItsCriticalLinesByKind) {
  const Ran r = run("discontinuity");
  ASSERT_TRUE(r.result.refined);
  EXPECT_GT(r["critical-segments"], 0);
  EXPECT_EQ(r["critical-segments"], static_cast<double>(r.result.refined->discontinuities.size()));
  EXPECT_EQ(r["critical-segments.extremal"] + r["critical-segments.interior"], r["critical-segments"]);
  EXPECT_EQ(r["critical-segments.ve"] + r["critical-segments.ev"], r["critical-segments"]);
  EXPECT_GT(r["critical-segments.extremal"], 0) << "umbra and penumbra boundaries";
  EXPECT_GT(r["critical-segments.interior"], 0) << "lines inside penumbrae";
  EXPECT_GT(r["critical-segments.ve"], 0);
  EXPECT_GT(r["critical-segments.ev"], 0);
  EXPECT_GT(r["elements"], r["elements.initial"]);
}

// The penumbra figure: many shadow rays soften the hard shadow, and a larger light widens the penumbra.
TEST(MeshingLesson, ALargerLightWidensThePenumbra) {
  const Ran r = run("penumbra");
  ASSERT_TRUE(r.result.raytrace);
  const RayTraceData& d = *r.result.raytrace;
  EXPECT_GT(rmsDifference(d.hard, d.whitted), 0.01 * r["mean.whitted"]);
  const Ran larger = run("penumbra", [](StepParameters& p) { p.lightSize = 3; });
  EXPECT_GT(rmsDifference(larger.result.raytrace->whitted, d.hard), rmsDifference(d.whitted, d.hard));
}

// Contact shadows: the floor is cut along the blocks' footprints (two blocks of four sides), the elements
// under the blocks receive nothing, and without the cut there are fewer elements and none of them is dark.
TEST(MeshingLesson, CuttingAtContactsLeavesTheFloorUnderTheBlocksDark) {
  const Ran r = run("contacts");
  EXPECT_EQ(r["contact-segments"], 8);
  auto darkFloorElements = [](const Ran& ran) {
    const StepResult& s = ran.result;
    int dark = 0;
    for (std::size_t e = 0; e < s.mesh.size(); ++e) {
      const auto& surface = s.scene.surfaces[s.scene.patches[s.mesh.elements[e].patch].surface];
      if (surface.name == "floor" && s.B.row(static_cast<Eigen::Index>(e)).maxCoeff() < 1e-6) ++dark;
    }
    return dark;
  };
  EXPECT_GT(darkFloorElements(r), 0);
  const Ran uncut = run("contacts", [](StepParameters& p) { p.splitAtContacts = false; });
  EXPECT_LT(uncut["elements"], r["elements"]);
  EXPECT_EQ(darkFloorElements(uncut), 0) << "every element straddling a footprint is partly lit";
}

// The T-vertex figure is the adaptive mesh drawn smooth: it has T-vertices, each on an edge of its element.
TEST(MeshingLesson, TheTVertexFigureHasTVerticesOnTheirLongEdges) {
  const Ran r = run("t-vertices");
  ASSERT_TRUE(r.result.refined);
  EXPECT_TRUE(r.step.parameters.smooth);
  EXPECT_GT(r["t-vertices"], 0);
  const Mesh& mesh = r.result.refined->mesh;
  for (const TVertex& t : r.result.refined->tVertices) {
    const Vec3 along = (1 - t.t) * mesh.vertices[t.edgeStart] + t.t * mesh.vertices[t.edgeEnd];
    EXPECT_LT((along - mesh.vertices[t.vertex]).norm(), 1e-6);
  }
}

}  // namespace
}  // namespace rt::lesson
