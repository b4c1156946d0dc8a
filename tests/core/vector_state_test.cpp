// The upper vector state is cleared where the work starts (core/vector_state.h): a library that leaves it in
// use makes every AVX2 maths call several times slower on some CPUs.
#include <gtest/gtest.h>

#include <atomic>

#include "core/formfactor/pair_matrix.h"
#include "core/progress.h"
#include "core/vector_state.h"
#include "support/dirty_vector_state.h"

TEST(VectorState, ClearingLeavesTheUpperHalvesUnused) {
  if (rt::upperVectorStateInUse() < 0) GTEST_SKIP() << "this CPU cannot tell whether the state is in use";
  rt::test::dirtyUpperVectorState();
  EXPECT_EQ(rt::upperVectorStateInUse(), 1);
  rt::clearUpperVectorState();
  EXPECT_EQ(rt::upperVectorStateInUse(), 0);
}

TEST(VectorState, EveryRowOfAPairMatrixStartsClean) {
  if (rt::upperVectorStateInUse() < 0) GTEST_SKIP() << "this CPU cannot tell whether the state is in use";
  std::atomic<int> rows{0}, dirty{0};
  rt::Progress progress;
  rt::FormFactorStats stats;
  rt::test::dirtyUpperVectorState();  // the calling thread, as a program's libraries leave it
  rt::forEachRow(200, {}, progress, "test", stats, [&](int, rt::RowCounters&) {
    ++rows;
    if (rt::upperVectorStateInUse() != 0) ++dirty;
    rt::test::dirtyUpperVectorState();  // and the next row on this thread must start clean again
  });
  rt::clearUpperVectorState();
  EXPECT_EQ(rows.load(), 200);
  EXPECT_EQ(dirty.load(), 0);
}
