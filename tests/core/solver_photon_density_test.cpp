// Continuous random walks (photon-density): photon trajectories traced through the scene, their hit points
// histogrammed per element. Through the pipeline they compute no form factor; on the Cornell box they agree
// with the direct solution of F by quadrature within their noise; in the furnace they give E / (1 - rho);
// and they differ from the discrete walks, which jump by F's rows, only by noise and discretisation.
#include <gtest/gtest.h>

#include <cmath>

#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/pipeline/pipeline.h"
#include "core/solvers/direct_solver.h"
#include "core/solvers/random_walks.h"
#include "core/solvers/solver.h"
#include "core/solvers/solver_support.h"
#include "support/test_paths.h"

namespace rt {
namespace {

PipelineSettings cornellSettings(const std::string& solver) {
  PipelineSettings settings;
  settings.mesh.mode = MeshOptions::Mode::Count;
  settings.mesh.count = 3;
  // Cut along the blocks' footprints: an element partly under a block sends part of its light into the
  // block in the linear system, while no photon lands there, and the two would differ by more than noise.
  settings.mesh.splitAtContacts = true;
  settings.method = "quadrature";
  settings.solver = solver;
  settings.solverOptions.raysPerIteration = 20000;
  settings.solverOptions.tolerance = 0.01;
  return settings;
}

TEST(PhotonDensity, ComputesNoFormFactorAndAgreesWithTheDirectSolutionWithinItsNoise) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  Pipeline walks;
  const PipelineOutput out = walks.run(scene, cornellSettings("photon-density"));
  EXPECT_EQ(out.F, nullptr);
  EXPECT_EQ(walks.formFactorComputations(), 0);
  ASSERT_EQ(out.solve.status, SolverStatus::Success);

  Pipeline direct;
  const PipelineOutput reference = direct.run(scene, cornellSettings("direct"));
  ASSERT_NE(reference.F, nullptr);
  const RgbField& B = out.solve.B;
  const RgbField& se = out.solve.standardErrors;
  double chi = 0;
  int count = 0;
  for (Eigen::Index i = 0; i < B.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      if (se(i, c) > 0) {
        chi += std::pow((B(i, c) - reference.solve.B(i, c)) / se(i, c), 2);
        ++count;
      }
  ASSERT_GT(count, 0);
  // Noise alone gives about 1; what is left above it is the constant elements' own error, which the
  // linear system makes and the photons do not (about 1 % on the blocks' faces).
  EXPECT_LE(std::sqrt(chi / count), 2.0);
  const double error =
      solver_detail::relativeAreaRms(B - reference.solve.B, reference.solve.B, out.mesh->areas());
  EXPECT_LT(error, 2.0 * out.solve.standardError) << "reported " << out.solve.standardError;
}

TEST(PhotonDensity, TheFurnaceGivesEOverOneMinusRho) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  PipelineSettings settings;
  settings.mesh.mode = MeshOptions::Mode::Count;
  settings.mesh.count = 2;
  settings.solver = "photon-density";
  settings.solverOptions.raysPerIteration = 20000;
  settings.solverOptions.tolerance = 0.005;
  Pipeline pipeline;
  const PipelineOutput out = pipeline.run(scene, settings);
  ASSERT_EQ(out.solve.status, SolverStatus::Success);
  for (Eigen::Index i = 0; i < out.solve.B.rows(); ++i)
    EXPECT_NEAR(out.solve.B(i, 0), 2.0, 5.0 * out.solve.standardErrors(i, 0)) << "element " << i;
}

TEST(PhotonDensity, NeedsTheGeometry) {
  RadiositySystem system;
  RgbField B;
  EXPECT_EQ(makeSolver("photon-density")->compute(system).solve().size(), 0);
  EXPECT_FALSE(solverNeedsMatrix("photon-density"));
  EXPECT_EQ(photonDensity(system, B, {}), SolverStatus::InvalidInput);
}

}  // namespace
}  // namespace rt
