// radiosity render: the two-pass picture, the solution's flat elements and the path tracer's picture of the
// closed Cornell box from one camera. The two-pass picture has no mesh artefacts, so it is the closer of the
// two to the path-traced one; a PNG is the picture at one exposure; a wrong output file is an input error.
#include <gtest/gtest.h>

#include "core/io/rgb_image.h"
#include "support/test_paths.h"
#ifdef RT_HAVE_VIZ
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#endif

namespace rt::test {
namespace {

const char* kSize = " --width 64 --height 64";

TEST(RenderCommand, TwoPassPictureIsCloserToThePathTracerThanTheFlatElements) {
  const std::string dir = scratchDir("render");
  const std::string base = cliPath() + " render " + sourcePath("scenes/cornell-box-closed.json") + kSize;
  std::string log;
  ASSERT_EQ(runCommand(base + " --path-trace 1024 --output " + dir + "/traced.pfm", &log), 0) << log;
  ASSERT_EQ(runCommand(base + " --flat --output " + dir + "/flat.pfm", &log), 0) << log;
  ASSERT_EQ(runCommand(base + " --gather-spacing 4 --output " + dir + "/two-pass.pfm", &log), 0) << log;
  EXPECT_NE(log.find("two-pass picture: 64x64 pixels"), std::string::npos) << log;
  const RgbImage traced = readPfm(dir + "/traced.pfm"), flat = readPfm(dir + "/flat.pfm"),
                 twoPass = readPfm(dir + "/two-pass.pfm");
  const double twoPassError = rmsDifference(twoPass, traced), flatError = rmsDifference(flat, traced);
  EXPECT_LT(twoPassError, 0.7 * flatError) << "two-pass " << twoPassError << ", flat " << flatError;
}

#ifdef RT_HAVE_VIZ
TEST(RenderCommand, PngIsThePictureAtOneExposure) {
  const std::string dir = scratchDir("render-png");
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " render " + sourcePath("scenes/cornell-box-closed.json") + kSize +
                           " --gather-rays 64 --camera doorway --output " + dir + "/two-pass.png",
                       &log),
            0)
      << log;
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName((dir + "/two-pass.png").c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], 64);
  ASSERT_EQ(dims[1], 64);
  // The exposure puts the mean at 18 % grey (sRGB about 118 of 255): neither black nor washed out.
  double sum = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      sum += (p[0] + p[1] + p[2]) / 3.0;
    }
  EXPECT_GT(sum / (64 * 64), 60);
  EXPECT_LT(sum / (64 * 64), 200);
}
#endif

TEST(RenderCommand, AnOutputThatIsNoPictureIsAnInputError) {
  const std::string dir = scratchDir("render-bad");
  std::string log;
  EXPECT_EQ(runCommand(cliPath() + " render " + sourcePath("scenes/cornell-box-closed.json") + kSize +
                           " --output " + dir + "/picture.jpg",
                       &log),
            3)
      << log;
  EXPECT_NE(log.find("--output"), std::string::npos) << log;
  EXPECT_NE(log.find(".png, .pfm or .ppm"), std::string::npos) << log;
}

}  // namespace
}  // namespace rt::test
