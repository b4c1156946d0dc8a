// End-to-end: the radiosity CLI solves the Cornell box and the scenes of the furnace test, from the files in
// scenes/.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"
#ifdef RT_HAVE_VIZ
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#endif

namespace rt::test {
namespace {

// In a convex enclosure `analytic` is exact to rounding, so B shows the solve to 1e-6 (the default method's
// tolerance of 1e-5 per entry would show in it).
TEST(SolveCommand, FurnaceCubeGivesEOverOneMinusRho) {
  const std::string out = scratchDir("solve-furnace") + "/B.csv";
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " solve " + sourcePath("scenes/furnace-cube.json") +
                           " --subdivide 2 --method analytic --output " + out,
                       &log),
            0)
      << log;
  const auto rows = readCsv(out);
  ASSERT_EQ(rows.size(), 1u + 6u * 4u);
  EXPECT_EQ(rows[0][0], "element");
  for (std::size_t r = 1; r < rows.size(); ++r)
    for (int c = 4; c < 7; ++c) EXPECT_NEAR(std::stod(rows[r][c]), 2.0, 1e-6) << "row " << r;
}

// Each element's centroid and normal follow B: the floor of the unit cube in 2 x 2 has its centroids at
// 0.25 and 0.75 and faces up.
TEST(SolveCommand, RadiosityCsvLocatesEachElement) {
  const std::string out = scratchDir("solve-geometry") + "/B.csv";
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " solve " + sourcePath("scenes/furnace-cube.json") +
                           " --subdivide 2 --output " + out,
                       &log),
            0)
      << log;
  const auto rows = readCsv(out);
  ASSERT_EQ(rows[0].size(), 13u);
  EXPECT_EQ(rows[0][7], "x");
  EXPECT_EQ(rows[0][12], "nz");
  int floorElements = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r][2] != "floor") continue;
    ++floorElements;
    EXPECT_EQ(std::stod(rows[r][8]), 0.0);   // y
    EXPECT_EQ(std::stod(rows[r][11]), 1.0);  // ny
    for (int c : {7, 9}) {
      const double v = std::stod(rows[r][c]);
      EXPECT_TRUE(std::abs(v - 0.25) < 1e-12 || std::abs(v - 0.75) < 1e-12) << v;
    }
    // Area times 4 is the floor's.
    EXPECT_NEAR(std::stod(rows[r][3]), 0.25, 1e-12);
  }
  EXPECT_EQ(floorElements, 4);
}

TEST(SolveCommand, ASceneWithoutMeshOptionsGetsAMeshAndSaysWhich) {
  // One element per polygon gave the JSON Cornell box 20 elements and 55 % error on the floor.
  const std::string out = scratchDir("solve-default-mesh") + "/B.csv";
  std::string log;
  ASSERT_EQ(
      runCommand(cliPath() + " solve " + sourcePath("scenes/cornell-box.json") + " --output " + out, &log), 0)
      << log;
  EXPECT_NE(
      log.find("mesh: no mesh option given: --max-edge 82 (mm) for about 849 elements, cut where surfaces "
               "stand on others"),
      std::string::npos)
      << log;
  const auto rows = readCsv(out);
  EXPECT_GE(rows.size(), 1u + 800u);
  // --no-subdivide still means one element per polygon, and says nothing.
  ASSERT_EQ(runCommand(cliPath() + " solve " + sourcePath("scenes/cornell-box.json") +
                           " --no-subdivide --output " + out,
                       &log),
            0)
      << log;
  EXPECT_EQ(log.find("no mesh option given"), std::string::npos) << log;
  EXPECT_EQ(readCsv(out).size(), 1u + 20u);
}

// An explicit --max-edge keeps the plain grid; --split-at-contacts adds the default mesh's cuts along the
// blocks' footprints, which make more elements, and the element centroids then never lie under a block.
TEST(SolveCommand, SplitAtContactsCutsAnExplicitGridAlongTheFootprints) {
  const std::string dir = scratchDir("solve-contacts");
  std::string log;
  const std::string base = cliPath() + " solve " + sourcePath("scenes/cornell-box.json") + " --max-edge 120";
  ASSERT_EQ(runCommand(base + " --output " + dir + "/plain.csv", &log), 0) << log;
  ASSERT_EQ(runCommand(base + " --split-at-contacts --output " + dir + "/cut.csv", &log), 0) << log;
  const auto plain = readCsv(dir + "/plain.csv"), cut = readCsv(dir + "/cut.csv");
  EXPECT_GT(cut.size(), plain.size() + 10);
  // The cut mesh has floor elements wholly under the blocks (B = 0), which together are the two footprints
  // (55,260 mm^2); on the plain grid every floor element under a block also reaches out beside it.
  auto darkFloorArea = [](const std::vector<std::vector<std::string>>& rows) {
    const int surface = column(rows[0], "surface"), area = column(rows[0], "area"),
              B = column(rows[0], "B_g");
    double sum = 0;
    for (std::size_t r = 1; r < rows.size(); ++r)
      if (rows[r][static_cast<std::size_t>(surface)] == "floor" &&
          std::stod(rows[r][static_cast<std::size_t>(B)]) == 0)
        sum += std::stod(rows[r][static_cast<std::size_t>(area)]);
    return sum;
  };
  EXPECT_NEAR(darkFloorArea(cut), 55259.5, 1.0);
  EXPECT_EQ(darkFloorArea(plain), 0.0);
  // Without a mesh to cut it is refused as contradictory.
  EXPECT_NE(runCommand(cliPath() + " solve " + sourcePath("scenes/cornell-box.json") +
                           " --no-subdivide --split-at-contacts --output " + dir + "/none.csv",
                       &log),
            0);
}

// The PLY export: a face per element with its B, a vertex per element corner; in the furnace every value
// is 2.
TEST(SolveCommand, PlyCarriesRadiosityPerFaceAndVertex) {
  const std::string out = scratchDir("solve-ply") + "/mesh.ply";
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " solve " + sourcePath("scenes/furnace-cube.json") +
                           " --subdivide 2 --method analytic --ply " + out,
                       &log),
            0)
      << log;
  std::ifstream in(out);
  std::string line;
  std::vector<std::string> header;
  while (std::getline(in, line) && line != "end_header") header.push_back(line);
  EXPECT_EQ(header[0], "ply");
  EXPECT_NE(std::find(header.begin(), header.end(), "element vertex 96"), header.end());
  EXPECT_NE(std::find(header.begin(), header.end(), "element face 24"), header.end());
  for (int v = 0; v < 96; ++v) {
    double x, y, z, r, g, b;
    int R, G, B;
    in >> x >> y >> z >> r >> g >> b >> R >> G >> B;
    ASSERT_TRUE(in) << "vertex " << v;
    EXPECT_NEAR(r, 2.0, 1e-5);  // smooth or flat, a uniform field stays 2
    EXPECT_EQ(R, 255);          // the brightest reflecting element is white
  }
  for (int f = 0; f < 24; ++f) {
    int count;
    in >> count;
    ASSERT_EQ(count, 4) << "face " << f;
    int index;
    for (int k = 0; k < count; ++k) {
      in >> index;
      EXPECT_EQ(index, 4 * f + k);
    }
    double r, g, b;
    int R, G, B;
    in >> r >> g >> b >> R >> G >> B;
    EXPECT_NEAR(r, 2.0, 1e-6);
  }
  EXPECT_TRUE(in);
}

TEST(SolveCommand, MissingSceneIsAClearError) {
  std::string log;
  EXPECT_NE(runCommand(cliPath() + " solve /nonexistent/scene.json", &log), 0);
  EXPECT_NE(log.find("scene.json"), std::string::npos) << log;
}

TEST(SolveCommand, UnknownSolverIsAClearError) {
  std::string log;
  EXPECT_NE(
      runCommand(cliPath() + " solve " + sourcePath("scenes/furnace-cube.json") + " --method nonsense", &log),
      0);
  EXPECT_NE(log.find("nonsense"), std::string::npos) << log;
}

#ifdef RT_HAVE_VIZ
TEST(SolveCommand, CornellBoxImageShowsColourBleeding) {
  const std::string dir = scratchDir("solve-cornell");
  std::string log;
  ASSERT_EQ(
      runCommand(cliPath() + " solve " + sourcePath("scenes/cornell-box.json") + " --max-edge 60 --output " +
                     dir + "/B.csv --image " + dir + "/cornell.png --width 400 --height 400",
                 &log),
      0)
      << log;
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName((dir + "/cornell.png").c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], 400);
  ASSERT_EQ(dims[1], 400);
  // Not blank: the pixels vary; the left third is reddish (red wall), the right third greenish (green wall).
  double sum = 0, sumSq = 0;
  double leftRed = 0, leftGreen = 0, rightRed = 0, rightGreen = 0;
  const int components = image->GetNumberOfScalarComponents();
  ASSERT_GE(components, 3);
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      const double lum = (p[0] + p[1] + p[2]) / 3.0;
      sum += lum;
      sumSq += lum * lum;
      if (y > dims[1] / 4 && y < 3 * dims[1] / 4) {
        if (x < dims[0] / 8) leftRed += p[0], leftGreen += p[1];
        if (x > 7 * dims[0] / 8) rightRed += p[0], rightGreen += p[1];
      }
    }
  const double n = dims[0] * dims[1];
  const double mean = sum / n, stddev = std::sqrt(std::max(0.0, sumSq / n - mean * mean));
  EXPECT_GT(mean, 20.0);
  EXPECT_GT(stddev, 10.0);
  EXPECT_GT(leftRed, 1.5 * leftGreen) << "the left (red) wall should look red";
  EXPECT_GT(rightGreen, 1.2 * rightRed) << "the right (green) wall should look green";
}

// --camera replaces the scene's view: from high up at the back wall looking out of the open side, the red
// wall is on the right and the green one on the left. A camera that cannot be read is an input error naming
// --camera.
TEST(SolveCommand, CameraOptionSetsTheView) {
  const std::string dir = scratchDir("solve-camera");
  std::string log;
  const std::string base = cliPath() + " solve " + sourcePath("scenes/cornell-box.json") +
                           " --max-edge 100 --width 200 --height 200 --image " + dir + "/turned.png";
  ASSERT_EQ(
      runCommand(base + " --camera 'position 278 500 550 target 278 350 0 up 0 1 0 fov_y_degrees 80'", &log),
      0)
      << log;
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName((dir + "/turned.png").c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  double leftRed = 0, leftGreen = 0, rightRed = 0, rightGreen = 0;
  for (int y = 70; y < 140; ++y)  // a band across the middle: walls at both sides, no block, no ceiling
    for (int x = 0; x < 200; ++x) {
      const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      if (x < 20) leftRed += p[0], leftGreen += p[1];
      if (x >= 180) rightRed += p[0], rightGreen += p[1];
    }
  EXPECT_GT(rightRed, 1.5 * rightGreen) << "the red wall should be on the right";
  EXPECT_GT(leftGreen, 1.2 * leftRed) << "the green wall should be on the left";
  EXPECT_EQ(runCommand(base + " --camera 'eye 1 2 3'", &log), 3) << log;
  EXPECT_NE(log.find("--camera: error: camera: unknown word 'eye'"), std::string::npos) << log;
}
#endif

}  // namespace
}  // namespace rt::test
