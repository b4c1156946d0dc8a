// One contract, every registered form-factor method (as tests/core/solver_contract_test.cpp is for the
// solvers): no negative entries; rows within 1 plus the method's own stated noise (a method that ignores
// occluders: or a warning that says so); reciprocity within the method's bound; the same matrix for the same
// seed; a cancelled Progress stops it with Cancelled; and its own knob (FormFactorMethod::knob()) converging
// on a reference case.
//
// The bounds are what each method states of itself: computed once per pair and mirrored (analytic,
// analytic-visibility, raycast, hybrid, quadrature) reciprocity holds to rounding; the centroid rules
// (hemicube, nusselt) measure from one point, which misses reciprocity by their point error;
// montecarlo's rows and pairs carry its binomial noise. A method registered without a row here fails the
// test: its promises must be written down.
//
// Written once, instantiated by each test binary over the methods it links: the core's in
// tests/core/formfactor_contract_test.cpp, the exact reference in tests/exact/formfactor_contract_test.cpp.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/formfactor/analytic.h"
#include "core/formfactor/formfactor_matrix.h"
#include "core/formfactor/formfactor_method.h"
#include "core/progress.h"
#include "formfactor_scenes.h"

namespace rt::test {

struct Promise {
  FormFactorOptions run;          // the setting the contract runs it at (its knob's default unless said)
  double rowSlack = 0;            // rows sum to at most 1 + this
  bool ignoresOccluders = false;  // rows above 1 in an occluded room, and a warning that says so
  // max |A_i F_ij - A_j F_ji| / (A_i + A_j): no more than the larger error of the two directions, in F
  double reciprocity = 0;
  bool fromCentroid = false;    // converges to the centroid's point-to-element value, not the average
  double coarse = 0, fine = 0;  // knob values for the convergence test
  double fineError = 0;         // the largest error allowed at `fine` on the reference case
};

inline bool promiseOf(const std::string& name, Promise& p) {
  p = {};
  if (name == "analytic") {
    p.rowSlack = 1e-9, p.ignoresOccluders = true, p.reciprocity = 1e-12, p.fineError = 1e-9;
  } else if (name == "analytic-visibility" || name == "raycast" || name == "hybrid") {
    // Rays: rows overshoot by their sampling noise, 0.8 % relative RMS at 256 samples
    // (docs/formfactor-methods.md), within the 1e-2 the methods that cast rays are allowed before a warning
    // (formfactor_method.cpp).
    p.run.samples = 256, p.rowSlack = 1e-2, p.reciprocity = 1e-12;
    p.coarse = 4, p.fine = 256, p.fineError = 1e-3;
  } else if (name == "quadrature") {
    p.rowSlack = -1;  // the tolerance per entry times the entries of a row, set below
    p.reciprocity = 1e-12, p.coarse = 1e-3, p.fine = 1e-7, p.fineError = 1e-7;
  } else if (name == "exact") {
    // Relative tolerance per entry, occluded pairs at 1e-7 or looser (exact_reference.h): at 1e-6 rows sum
    // to 1 within a few 1e-7, and each pair is computed once and mirrored.
    p.run.tolerance = 1e-6, p.rowSlack = 1e-6, p.reciprocity = 1e-12;
    p.coarse = 1e-3, p.fine = 1e-9, p.fineError = 1e-12;
  } else if (name == "montecarlo") {
    // Binomial noise sqrt(F (1 - F) / N) per entry, N rays per element: at most 1.6e-3 at N = 100,000, 5
    // sigma 8e-3 for either direction of a pair. Rows: every ray hits a wall but for the odd one slipping
    // through a corner in single precision.
    p.run.samples = 100000, p.rowSlack = 1e-3, p.reciprocity = 8e-3;
    p.coarse = 100, p.fine = 100000, p.fineError = 1e-2;
  } else if (name == "hemicube") {
    // From the centroid: 5e-2 off for adjacent faces of a cube (formfactor_methods_test.cpp), and the bound
    // allows twice that for elements of unequal sizes (a block's faces against the floor); the delta form
    // factors sum to 1 and every pixel sees a wall.
    p.rowSlack = 1e-9, p.reciprocity = 0.1, p.fromCentroid = true;
    p.coarse = 16, p.fine = 1024, p.fineError = 2e-3;
  } else if (name == "nusselt") {
    // From the centroid, occluders ignored (the lesson's picture of Lambert's formula).
    p.rowSlack = 2e-3, p.ignoresOccluders = true, p.reciprocity = 0.1, p.fromCentroid = true;
    p.coarse = 8, p.fine = 1024, p.fineError = 1e-4;
  } else {
    return false;
  }
  return true;
}

class FormFactorContract : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    ASSERT_TRUE(promiseOf(GetParam(), promise_)) << "write down what " << GetParam() << " promises";
  }
  FormFactorMatrix run(const Mesh& mesh, FormFactorOptions options, FormFactorStats* stats = nullptr) const {
    return test::runMethod(GetParam(), mesh, options, stats);
  }
  Promise promise_;
};

// The room with a block on a 2 x 2 mesh: occluded pairs, a closed scene.
TEST_P(FormFactorContract, NoNegativeEntriesRowsWithinTheirNoiseReciprocal) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 2);
  FormFactorStats stats;
  const FormFactorMatrix F = run(mesh, promise_.run, &stats);
  ASSERT_EQ(F.rows(), static_cast<Eigen::Index>(mesh.size()));
  ASSERT_TRUE(F.allFinite());
  EXPECT_GE(F.minCoeff(), 0.0);
  const double slack = promise_.rowSlack >= 0
                           ? promise_.rowSlack
                           : accuracyKnobOf(GetParam()).defaultValue * static_cast<double>(mesh.size());
  const double rows = F.rowwise().sum().maxCoeff();
  if (promise_.ignoresOccluders)
    EXPECT_TRUE(rows <= 1 + slack || !stats.warnings.empty()) << "rows up to " << rows << " without a word";
  else
    EXPECT_LE(rows, 1 + slack);
  const Eigen::VectorXd areas = mesh.areas();
  double gap = 0;
  for (Eigen::Index i = 0; i < F.rows(); ++i)
    for (Eigen::Index j = 0; j < F.cols(); ++j)
      gap = std::max(gap, std::abs(areas(i) * F(i, j) - areas(j) * F(j, i)) / (areas(i) + areas(j)));
  EXPECT_LE(gap, promise_.reciprocity);
}

TEST_P(FormFactorContract, SameSeedSameMatrix) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 2);
  FormFactorOptions options = promise_.run;
  options.seed = 3;
  const FormFactorMatrix a = run(mesh, options), b = run(mesh, options);
  EXPECT_EQ((a - b).cwiseAbs().maxCoeff(), 0.0);
}

TEST_P(FormFactorContract, ACancelledProgressStopsItWithCancelled) {
  const Mesh mesh = test::meshOf(test::roomWithBlock(), 2);
  CallbackProgress progress(nullptr);
  progress.cancel();
  FormFactorStats stats;
  EXPECT_THROW(makeFormFactorMethod(GetParam())->compute(mesh, {}, progress, stats), Cancelled);
}

// Two parallel unit squares one apart, 2 x 2 elements each: the analytic matrix is exact (the centroid
// rules converge to the centroid's point-to-element values instead).
TEST_P(FormFactorContract, ItsKnobConvergesOnTheReferenceCase) {
  Scene s = test::emptyScene();
  test::addQuad(s, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  test::addQuad(s, {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1});
  const Mesh mesh = test::meshOf(s, 2);
  FormFactorMatrix expected = test::runMethod("analytic", mesh);
  if (promise_.fromCentroid)
    for (Eigen::Index i = 0; i < expected.rows(); ++i)
      for (Eigen::Index j = 0; j < expected.cols(); ++j)
        expected(i, j) = i == j
                             ? 0
                             : pointToPolygonFormFactor(mesh.elements[static_cast<std::size_t>(i)].centroid,
                                                        mesh.elements[static_cast<std::size_t>(i)].normal,
                                                        mesh.polygon(static_cast<int>(j)));
  const AccuracyKnob knob = makeFormFactorMethod(GetParam())->knob();
  auto errorAt = [&](double value) {
    return (run(mesh, knob.applied({}, value)) - expected).cwiseAbs().maxCoeff();
  };
  if (knob.field == AccuracyKnob::Field::None) {
    EXPECT_LE(errorAt(0), promise_.fineError);
    return;
  }
  const double coarse = errorAt(promise_.coarse), fine = errorAt(promise_.fine);
  EXPECT_LE(fine, promise_.fineError)
      << knob.name << " " << promise_.fine << " (at " << promise_.coarse << ": " << coarse << ")";
  EXPECT_LE(fine, std::max(coarse, promise_.fineError)) << "finer " << knob.name << " made it worse";
}

}  // namespace rt::test
