// The app's computations run with the upper vector state clean (core/vector_state.h), whatever the GUI
// thread's libraries left in it: the web engine's QML stack leaves it in use from its static initialisers,
// and the maths library's AVX2 functions then run several times slower on some CPUs.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <atomic>

#include "app/computation_runner.h"
#include "core/vector_state.h"
#include "support/dirty_vector_state.h"

using rt::app::ComputationRunner;
using rt::app::PipelineResult;

TEST(AppVectorState, ComputationsStartWithTheUpperHalvesUnused) {
  if (rt::upperVectorStateInUse() < 0) GTEST_SKIP() << "this CPU cannot tell whether the state is in use";
  rt::test::dirtyUpperVectorState();  // as the libraries leave the GUI thread (and every thread created from
                                      // it)
  ASSERT_EQ(rt::upperVectorStateInUse(), 1);
  ComputationRunner runner;
  QSignalSpy finished(&runner, &ComputationRunner::finished);
  std::atomic<int> seen{-2};
  runner.start([&](rt::Progress&) {
    seen = rt::upperVectorStateInUse();
    return PipelineResult{};
  });
  ASSERT_TRUE(finished.wait(10000));
  EXPECT_EQ(seen.load(), 0);

  // On the calling thread too (screenshots and tests run the pipeline there).
  rt::test::dirtyUpperVectorState();
  ASSERT_EQ(rt::upperVectorStateInUse(), 1);
  seen = -2;
  runner.runBlocking([&](rt::Progress&) {
    seen = rt::upperVectorStateInUse();
    return PipelineResult{};
  });
  EXPECT_EQ(seen.load(), 0);
}
