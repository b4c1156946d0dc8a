// The meshing views' data: which links a leaf gathers over, the kinds of critical lines, and the T-vertices
// the T-vertex view marks.
#include <gtest/gtest.h>

#include "core/io/scene_loader.h"
#include "core/polygon.h"
#include "support/test_paths.h"
#include "viz/meshing_view.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

RefinedSolution cornellBox(RefineMode mode) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box.json"));
  RefineOptions options;
  options.mode = mode;
  options.visibilitySamples = 4;
  return solveRefined(scene, options);
}

TEST(LinksView, EveryLeafGathersOverLinksOfItselfOrItsAncestors) {
  const RefinedSolution s = cornellBox(RefineMode::Hierarchical);
  ASSERT_FALSE(s.links.empty());
  std::size_t total = 0;
  for (std::size_t e = 0; e < s.mesh.size(); ++e) {
    const std::vector<int> links = linksGatheredBy(s, static_cast<int>(e));
    EXPECT_FALSE(links.empty()) << "leaf " << e << " gathers nothing";
    const Element& leaf = s.mesh.elements[e];
    for (int k : links) {
      const HierarchyLink& link = s.links[static_cast<std::size_t>(k)];
      // The receiving node is the leaf or one of its ancestors: as large or larger, and no deeper.
      EXPECT_GE(polygonArea(link.to), leaf.area * (1 - 1e-9));
      EXPECT_LE(link.toLevel, s.elementLevel[e]);
    }
    total += links.size();
  }
  EXPECT_GE(total, s.links.size() / 2);  // links of large nodes count once per leaf below them
  EXPECT_THROW(linksGatheredBy(s, static_cast<int>(s.mesh.size())), std::invalid_argument);
}

TEST(LinksView, NeedsAHierarchy) {
  const RefinedSolution s = cornellBox(RefineMode::Uniform);
  EXPECT_THROW(writeLinksFigure(s, Camera{}, {}, test::scratchDir("links") + "/none.png"),
               std::invalid_argument);
  EXPECT_EQ(linkColouringFromName("formfactor"), LinkColouring::FormFactor);
  EXPECT_THROW(linkColouringFromName("bf"), std::invalid_argument);
}

TEST(DiscontinuityView, CountsBothKindsOfCriticalLines) {
  const RefinedSolution s = cornellBox(RefineMode::Discontinuity);
  const CriticalLineCounts counts = countCriticalLines(s);
  EXPECT_EQ(counts.extremal + counts.interior, s.discontinuities.size());
  EXPECT_GT(counts.extremal, 0u);  // the blocks cast shadows with umbra and penumbra boundaries
}

// The T-vertex view draws every hanging vertex and its long edge over the mesh: without them the same
// picture differs, and the caption counts them.
TEST(TVertexView, MarksTheHangingVerticesOverTheMesh) {
  const RefinedSolution s = cornellBox(RefineMode::Adaptive);
  ASSERT_FALSE(s.tVertices.empty());
  Camera camera;
  camera.position = {278, 273, -800};
  camera.target = {278, 273, 280};
  DiscontinuityViewOptions options;
  options.size = {480, 360, 96.0};
  const std::string dir = test::scratchDir("t-vertices");
  const std::string caption = writeTVertexFigure(s, camera, options, dir + "/marked.png");
  EXPECT_NE(caption.find(std::to_string(s.tVertices.size()) + " T-vertices"), std::string::npos) << caption;
  RefinedSolution unmarked = s;
  unmarked.tVertices.clear();
  writeTVertexFigure(unmarked, camera, options, dir + "/unmarked.png");
  EXPECT_GT(vizt::pngDifference(dir + "/marked.png", dir + "/unmarked.png"), 0.5);
}

}  // namespace
}  // namespace rt::viz
