// The display pipeline and colour maps against known values.
#include <gtest/gtest.h>

#include "viz/colour_map.h"
#include "viz/display_pipeline.h"

namespace rt::viz {
namespace {

TEST(DisplayPipeline, SrgbCurveKnownValues) {
  EXPECT_DOUBLE_EQ(linearToSrgb(0.0), 0.0);
  EXPECT_NEAR(linearToSrgb(1.0), 1.0, 1e-12);
  EXPECT_NEAR(linearToSrgb(0.0031308), 12.92 * 0.0031308, 1e-9);
  EXPECT_NEAR(linearToSrgb(0.5), 0.735357, 1e-6);  // the usual mid grey
  EXPECT_NEAR(linearToSrgb(0.18), 0.461356, 1e-6);
}

TEST(DisplayPipeline, LinearClampAndReinhard) {
  DisplaySettings linear{2.0, ToneMap::LinearClamp, false};
  EXPECT_DOUBLE_EQ(displayChannel(0.25, linear), 0.5);
  EXPECT_DOUBLE_EQ(displayChannel(3.0, linear), 1.0);
  EXPECT_DOUBLE_EQ(displayChannel(-1.0, linear), 0.0);
  DisplaySettings reinhard{1.0, ToneMap::Reinhard, false};
  EXPECT_DOUBLE_EQ(displayChannel(1.0, reinhard), 0.5);
  EXPECT_DOUBLE_EQ(displayChannel(3.0, reinhard), 0.75);
  const Rgb8 white = displayColour(Rgb(10, 10, 10), linear);
  EXPECT_EQ(white[0], 255);
}

TEST(DisplayPipeline, AutoExposureIgnoresEmitters) {
  RgbField B(11, 3), E = RgbField::Zero(11, 3);
  for (int i = 0; i < 10; ++i) B.row(i).setConstant(i + 1.0);  // 1..10
  B.row(10).setConstant(1000.0);
  E.row(10).setConstant(1000.0);
  // 90th percentile of 1..10 (rank 8 of 0..9) is 9: linear maps 9 to white.
  EXPECT_DOUBLE_EQ(autoExposure(B, ToneMap::LinearClamp, &E), 1.0 / 9.0);
  EXPECT_DOUBLE_EQ(autoExposure(B, ToneMap::Reinhard, &E), 2.0 / 9.0);
  EXPECT_DOUBLE_EQ(autoExposure(RgbField::Zero(3, 3), ToneMap::LinearClamp), 1.0);
  ImageOptions fixed;
  fixed.exposure = 0.5;
  EXPECT_DOUBLE_EQ(displaySettingsFor(fixed, B).exposure, 0.5);
}

TEST(ColourMap, EndpointsAndMonotoneLightness) {
  const Rgb8 low = sampleColourMap(ColourMap::Viridis, 0.0), high = sampleColourMap(ColourMap::Viridis, 1.0);
  EXPECT_EQ(low, (Rgb8{0x44, 0x01, 0x54}));
  EXPECT_EQ(high, (Rgb8{0xfd, 0xe7, 0x25}));
  for (ColourMap map : {ColourMap::Viridis, ColourMap::Cividis, ColourMap::Grey}) {
    double previous = -1;
    for (int k = 0; k <= 50; ++k) {
      const auto c = sampleColourMapUnit(map, k / 50.0);
      const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
      EXPECT_GT(luma, previous - 1e-9) << toString(map) << " at " << k;
      previous = luma;
    }
  }
  EXPECT_EQ(colourMapFromName("cividis"), ColourMap::Cividis);
  EXPECT_THROW(colourMapFromName("jet"), std::invalid_argument);
}

TEST(ColourMap, CategoryColoursDifferForNeighbours) {
  for (int i = 0; i < 40; ++i) EXPECT_NE(categoryColour(i), categoryColour(i + 1));
}

}  // namespace
}  // namespace rt::viz
