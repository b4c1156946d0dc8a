// The segment's parameter range clipped by half-spaces (core/geometry/segment_clip.h): each convention of
// the header (where the range narrows, a parallel segment on an Open or a Closed boundary, a range narrowed
// to a point). The clips built on it keep their own tests (shadow_clipper_test.cpp,
// refine_discontinuity_test.cpp, contact_lines_test.cpp).
#include "core/geometry/segment_clip.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(GeometrySegmentClip, TheRangeNarrowsFromBelowOrAboveByTheRatesSign) {
  double t0 = 0, t1 = 1;
  // 0.25 - ... : f(t) = -0.25 + t, inside from t = 0.25 on.
  EXPECT_TRUE(clipRange(-0.25, 1.0, 0.0, Boundary::Open, t0, t1));
  EXPECT_EQ(t0, 0.25);
  EXPECT_EQ(t1, 1.0);
  // f(t) = 0.75 - t: inside up to t = 0.75.
  EXPECT_TRUE(clipRange(0.75, -1.0, 0.0, Boundary::Closed, t0, t1));
  EXPECT_EQ(t0, 0.25);
  EXPECT_EQ(t1, 0.75);
  // A half-space that holds the whole segment changes nothing.
  EXPECT_TRUE(clipRange(5.0, 1.0, 0.0, Boundary::Open, t0, t1));
  EXPECT_EQ(t0, 0.25);
}

// A range narrowed to one point is empty, whatever the boundary.
TEST(GeometrySegmentClip, ARangeOfOnePointIsEmpty) {
  for (Boundary boundary : {Boundary::Open, Boundary::Closed}) {
    double t0 = 0, t1 = 1;
    EXPECT_TRUE(clipRange(-0.5, 1.0, 0.0, boundary, t0, t1));
    EXPECT_FALSE(clipRange(0.5, -1.0, 0.0, boundary, t0, t1));
  }
}

// Parallel to the boundary and on it: kept by a Closed boundary, dropped by an Open one; inside by any
// amount, kept by both; outside, dropped by both. Rates up to `parallel` count as parallel.
TEST(GeometrySegmentClip, AParallelSegmentOnTheBoundaryIsInOnlyForAClosedOne) {
  double t0 = 0, t1 = 1;
  EXPECT_TRUE(clipRange(0.0, 0.0, 0.0, Boundary::Closed, t0, t1));
  EXPECT_FALSE(clipRange(0.0, 0.0, 0.0, Boundary::Open, t0, t1));
  EXPECT_TRUE(clipRange(1e-20, 0.0, 0.0, Boundary::Open, t0, t1));
  EXPECT_FALSE(clipRange(-1e-20, 0.0, 0.0, Boundary::Closed, t0, t1));
  EXPECT_TRUE(clipRange(0.0, kTinyRate, kTinyRate, Boundary::Closed, t0, t1));
  EXPECT_FALSE(clipRange(-1.0, kTinyRate, kBelowTinyRate, Boundary::Closed, t0, t1));  // not parallel: t huge
  EXPECT_LT(kBelowTinyRate, kTinyRate);
}

}  // namespace
}  // namespace rt
