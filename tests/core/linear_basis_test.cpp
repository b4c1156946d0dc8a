// The linear basis (core/basis): its nodes and shape functions, the weighted point-to-element form factors,
// the furnace, reciprocity, convergence of order 2 against order 1 for constant elements on a smooth case,
// and agreement with the constant basis as the mesh refines.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/basis/linear_kernel.h"
#include "core/basis/radiosity_field.h"
#include "core/formfactor/analytic.h"
#include "core/io/scene_loader.h"
#include "core/pipeline/linear_solve.h"
#include "core/pipeline/pipeline.h"
#include "core/power_law.h"
#include "support/test_paths.h"

namespace rt {
namespace {

Mesh gridMesh(const Scene& scene, int count) {
  MeshOptions o;
  o.mode = MeshOptions::Mode::Count;
  o.count = count;
  return buildMesh(scene, o);
}

TEST(LinearBasis, NodesPerPatchVertexAndWeightsAddUpToTheArea) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  const Mesh mesh = gridMesh(scene, 3);
  const LinearBasis basis = buildLinearBasis(mesh);
  EXPECT_EQ(basis.size(), 6u * 16u);  // a 4 x 4 grid of vertices on each face, none shared across faces
  EXPECT_NEAR(basis.weights.sum(), mesh.areas().sum(), 1e-12);
  // A corner node of a face carries a quarter of one element, an interior node four quarters.
  EXPECT_NEAR(basis.weights.minCoeff(), 0.25 / 9, 1e-12);
  EXPECT_NEAR(basis.weights.maxCoeff(), 1.0 / 9, 1e-12);
}

TEST(LinearBasis, RefusesElementsOfMoreThanFourCorners) {
  Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  Mesh mesh = buildMesh(scene);
  mesh.elements[0].vertices.push_back(mesh.elements[0].vertices[0]);
  EXPECT_THROW(buildLinearBasis(mesh), InputError);
}

TEST(LinearBasis, WeightedFormFactorsSplitLambertsTotal) {
  const Scene scene = loadScene(test::sourcePath("scenes/parallel-squares.json"));
  const Mesh mesh = buildMesh(scene);
  // From the centre of the receiver, the source (element 0) is symmetric: four equal shares.
  const Vec3 centre(0.5, 0.5, 1.0), down(0, 0, -1);
  const WeightedFormFactor w = weightedPointFormFactor(centre, down, mesh, 0, 1e-8);
  ASSERT_EQ(w.count, 4);
  EXPECT_NEAR(w.total, pointToPolygonFormFactor(centre, down, mesh.polygon(0)), 1e-15);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(w.shares[k], w.total / 4, 1e-12);
  // Close above a corner, the nearest corner takes most of it, and the shares still add up.
  const Vec3 low(0.1, 0.1, 0.05);
  const WeightedFormFactor near = weightedPointFormFactor(low, down, mesh, 0, 1e-8);
  EXPECT_NEAR(near.shares[0] + near.shares[1] + near.shares[2] + near.shares[3], near.total, 1e-12);
  EXPECT_GT(near.shares[0], 0.5 * near.total);
  EXPECT_GE(near.order, 8);
}

TEST(LinearBasis, FurnaceGivesEOverOneMinusRhoAtEveryNode) {
  const Scene scene = loadScene(test::sourcePath("scenes/furnace-cube.json"));
  const Mesh mesh = gridMesh(scene, 3);
  const auto kernel = computeLinearKernel(mesh, {}, noProgress());
  // Every row sums to 1: each point of a closed cube sees all of it, and the shares add up exactly.
  const Eigen::VectorXd rows = kernel->K.rowwise().sum();
  EXPECT_LT((rows.array() - 1.0).abs().maxCoeff(), 1e-12);
  const SolveOutcome out = solveLinearBasis(*kernel, "direct", {}, false, noProgress());
  ASSERT_EQ(out.status, SolverStatus::Success);
  ASSERT_EQ(out.nodal.rows(), static_cast<Eigen::Index>(kernel->basis.size()));
  const double expected = 1.0 / (1.0 - 0.5);
  EXPECT_LT((out.nodal.array() - expected).abs().maxCoeff(), 1e-10);
  EXPECT_LT((out.B.array() - expected).abs().maxCoeff(), 1e-10);
  EXPECT_LT((out.corners.array() - expected).abs().maxCoeff(), 1e-10);
}

TEST(LinearBasis, EachRowSumsToWhatItsNodeSees) {
  const Scene scene = loadScene(test::sourcePath("scenes/perpendicular-squares.json"));
  const Mesh mesh = gridMesh(scene, 4);
  const auto kernel = computeLinearKernel(mesh, {}, noProgress());
  const Polygon source{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  int checked = 0;
  for (std::size_t v = 0; v < kernel->basis.size(); ++v) {
    if (kernel->basis.nodePatch[v] != 1) continue;
    const Vec3 x = mesh.vertices[static_cast<std::size_t>(kernel->basis.nodeVertex[v])];
    // Off the shared edge by a hair, where Lambert's formula is defined (the kernel moves its nodes so too).
    const Vec3 inside = x + 1e-7 * (Vec3(0.5, 0, 0.5) - x);
    const double sees = pointToPolygonFormFactor(inside, Vec3(0, 1, 0), source);
    EXPECT_NEAR(kernel->K.row(static_cast<Eigen::Index>(v)).sum(), sees, 1e-5) << "node at " << x.transpose();
    EXPECT_GE(kernel->K.row(static_cast<Eigen::Index>(v)).minCoeff(), 0.0);
    ++checked;
  }
  EXPECT_EQ(checked, 25);
}

// Two unit squares facing each other at distance 1; the lower one emits 1 and reflects nothing, so the
// upper one's radiosity is exactly rho F(x -> source), Lambert's formula at every point.
struct ParallelSquares {
  Scene scene = loadScene(test::sourcePath("scenes/parallel-squares.json"));
  double rho = 0.5;
  Rgb exact(const Vec3& x, int patch) const {
    if (patch == 0) return Rgb::Ones();
    const Polygon source{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    return Rgb::Constant(rho * pointToPolygonFormFactor(x, Vec3(0, 0, -1), source));
  }
  // The relative L1 error of each basis on the receiver at a count x count mesh.
  void errors(int count, double& constant, double& linear, double* difference = nullptr) const {
    const Mesh mesh = gridMesh(scene, count);
    Pipeline pipeline;
    PipelineSettings settings;
    settings.mesh.mode = MeshOptions::Mode::Count;
    settings.mesh.count = count;
    settings.solver = "direct";
    const PipelineOutput c = pipeline.run(scene, settings);
    settings.basis = Basis::Linear;
    const PipelineOutput l = pipeline.run(scene, settings);
    ASSERT_TRUE(l.linear);
    const auto exactAt = [this](const Vec3& x, int patch) { return exact(x, patch); };
    const auto receiver = [](int patch) { return patch == 1; };
    const RadiosityField constantField(*c.mesh, c.solve.B);
    const RadiosityField linearField(*l.mesh, l.linear->basis, l.solve.nodal);
    constant = relativeL1Difference(constantField, exactAt, 6, receiver);
    linear = relativeL1Difference(linearField, exactAt, 6, receiver);
    if (difference) *difference = relativeL1Difference(constantField, linearField, 6, receiver);
  }
};

TEST(LinearBasis, ConvergesWithOrderTwoWhereConstantElementsConvergeWithOrderOne) {
  const ParallelSquares squares;
  std::vector<double> h, constant, linear;
  for (const int count : {4, 8, 16}) {
    double c = 0, l = 0;
    squares.errors(count, c, l);
    h.push_back(1.0 / count);
    constant.push_back(c);
    linear.push_back(l);
  }
  const double constantOrder = logLogSlope(h, constant);
  const double linearOrder = logLogSlope(h, linear);
  EXPECT_NEAR(constantOrder, 1.0, 0.2) << "constant errors " << constant[0] << ", " << constant[2];
  EXPECT_NEAR(linearOrder, 2.0, 0.25) << "linear errors " << linear[0] << ", " << linear[2];
  EXPECT_LT(linear.back(), 0.2 * constant.back());
}

TEST(LinearBasis, AgreesWithTheConstantBasisAsTheMeshRefines) {
  const ParallelSquares squares;
  double c = 0, l = 0, coarse = 0, fine = 0;
  squares.errors(4, c, l, &coarse);
  squares.errors(16, c, l, &fine);
  // Four times finer, the two differ by about a quarter as much: both converge to the same function.
  EXPECT_LT(fine, 0.35 * coarse);
  EXPECT_LT(fine, 0.02);
}

TEST(LinearBasis, PipelineRefusesSolversThatTraceRaysAndOtherMethods) {
  const Scene scene = loadScene(test::sourcePath("scenes/parallel-squares.json"));
  Pipeline pipeline;
  PipelineSettings settings;
  settings.mesh.mode = MeshOptions::Mode::Count;
  settings.mesh.count = 2;
  settings.basis = Basis::Linear;
  settings.solver = "local-lines";
  EXPECT_THROW(pipeline.run(scene, settings), InputError);
  settings.solver = "jacobi";
  settings.method = "hemicube";
  EXPECT_THROW(pipeline.run(scene, settings), InputError);
  EXPECT_FALSE(linearBasisProblem("local-lines", "").empty());
  EXPECT_FALSE(linearBasisProblem("stochastic-jacobi", "").empty());
  EXPECT_TRUE(linearBasisProblem("gauss-seidel", defaultFormFactorMethod()).empty());
}

}  // namespace
}  // namespace rt
