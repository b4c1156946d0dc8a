// Every mesh that follows the light keeps the power balance of a closed room: what the light emits is
// absorbed, up to the form-factor error of the refined mesh (row sums of the transfers, visibility rays).
#include <gtest/gtest.h>

#include <ostream>

#include "core/refine/refine.h"
#include "refine_energy.h"
#include "refine_test_scenes.h"

namespace rt {

// Test names and messages show the mode, not the bytes of the enum.
void PrintTo(RefineMode mode, std::ostream* os) {
  *os << toString(mode);
}

namespace {

class RefineEnergy : public ::testing::TestWithParam<RefineMode> {};

TEST_P(RefineEnergy, ClosedRoomAbsorbsWhatItEmits) {
  RefineOptions o;
  o.mode = GetParam();
  o.initialMaxEdge = 0.7;
  o.maxPasses = 3;
  o.maxElements = 600;
  o.linkTolerance = 0.01;
  o.minArea = 0.1 * 0.1;
  const RefinedSolution s = solveRefined(test::closedRoom(), o);
  EXPECT_GT(s.stats.elements, 0u);
  const Eigen::Array3d ratio = test::absorbedOverEmitted(s);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(ratio[c], 1.0, 0.03) << toString(o.mode) << ": " << s.stats.summary();
}

INSTANTIATE_TEST_SUITE_P(EveryMode, RefineEnergy,
                         ::testing::Values(RefineMode::Uniform, RefineMode::Adaptive,
                                           RefineMode::Discontinuity, RefineMode::Hierarchical),
                         [](const ::testing::TestParamInfo<RefineMode>& info) {
                           return toString(info.param);
                         });

}  // namespace
}  // namespace rt
