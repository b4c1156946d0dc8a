// The two-pass picture with the gathered light on a grid of pixels: against a long path-traced image of a
// room whose block casts shadows on the floor, it is as close as the picture that gathers at every pixel with
// the same rays in all, and its shadow edges stay as sharp (the direct light is exact at every pixel); its
// silhouettes are averaged over the pixel, as the path tracer's are.
#include <gtest/gtest.h>

#include "core/pathtrace/image_compare.h"
#include "core/pathtrace/path_tracer.h"
#include "core/pathtrace/two_pass.h"
#include "core/pipeline/pipeline.h"
#include "formfactor_scenes.h"

namespace rt {
namespace {

TEST(TwoPassImage, GatheringOnAGridIsAsCloseToThePathTracerForTheSameRays) {
  const Scene scene = test::roomWithBlock();  // a unit room, the top emits, a block on the floor
  PipelineSettings settings;
  settings.mesh.mode = MeshOptions::Mode::Count;
  settings.mesh.count = 8;
  settings.method = "raycast";
  settings.formFactors.samples = 64;
  Pipeline pipeline;
  const PipelineOutput solved = pipeline.run(scene, settings);
  const PathTracer tracer(scene);
  const TwoPass twoPass(tracer.tracing(), *solved.mesh, solved.solve.B, solved.F.get());
  const Camera camera{{0.5, 0.05, 0.9}, {0.5, 0.6, 0}, {0, 0, 1}, 70};
  constexpr int kSize = 64;
  PathTraceOptions traceOptions;
  traceOptions.samples = 2048;
  const TracedImage reference = tracer.render(camera, kSize, kSize, traceOptions);

  TwoPassOptions everyPixel;
  everyPixel.gatherRays = 64;
  const RgbImage dense = twoPass.render(camera, kSize, kSize, everyPixel, 1);
  TwoPassOptions grid = everyPixel;
  grid.gatherRays = 64 * 16;  // every 4th pixel of a row and column: the same rays in all
  const RgbImage sparse = twoPass.render(camera, kSize, kSize, grid, 4);

  const ImageError denseError = compareToReference(dense, reference);
  const ImageError sparseError = compareToReference(sparse, reference);
  EXPECT_LT(sparseError.error, denseError.error)
      << "grid " << sparseError.error << ", every pixel " << denseError.error;
  // The shadow's edge on the floor: the largest jump between neighbouring pixels of a row is as large as in
  // the picture that gathers everywhere (the exact direct light is not smoothed by the interpolation).
  auto sharpest = [&](const RgbImage& image) {
    double jump = 0;
    for (int y = kSize / 2; y < kSize; ++y)
      for (int x = 1; x < kSize; ++x)
        jump = std::max(jump, std::abs(image.at(x, y)(1) - image.at(x - 1, y)(1)));
    return jump;
  };
  EXPECT_GT(sharpest(sparse), 0.8 * sharpest(dense));

  // The block's silhouettes: taking each pixel's centre alone makes every pixel along them wrong by the whole
  // step in brightness; the picture averages samples over those pixels, as the path tracer does.
  TwoPassOptions centresOnly = grid;
  centresOnly.edgeSamples = 1;
  const ImageError centresError =
      compareToReference(twoPass.render(camera, kSize, kSize, centresOnly, 4), reference);
  EXPECT_LT(sparseError.error, 0.8 * centresError.error)
      << "samples over edge pixels " << sparseError.error << ", centres only " << centresError.error;
}

}  // namespace
}  // namespace rt
