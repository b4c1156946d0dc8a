#include "core/time_left.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rt {
namespace {

TEST(TimeLeft, SaysNothingUntilTheEstimateMeansSomething) {
  EXPECT_EQ(describeTimeLeft(2, 0.5), "");     // too early
  EXPECT_EQ(describeTimeLeft(60, 0.005), "");  // too little done
  EXPECT_EQ(describeTimeLeft(60, 1.0), "");    // done
  EXPECT_EQ(describeTimeLeft(NAN, 0.5), "");   // no clock
}

TEST(TimeLeft, ExtrapolatesTheRateInReadableUnits) {
  EXPECT_EQ(describeTimeLeft(10, 0.5), "about 10 s left");
  EXPECT_EQ(describeTimeLeft(6, 0.9), "about 5 s left");      // never "0 s" while running
  EXPECT_EQ(describeTimeLeft(30, 0.25), "about 2 min left");  // 90 s and more: minutes
  EXPECT_EQ(describeTimeLeft(200, 0.1), "about 30 min left");
  EXPECT_EQ(describeTimeLeft(600, 0.05), "about 3 h 10 min left");
}

}  // namespace
}  // namespace rt
