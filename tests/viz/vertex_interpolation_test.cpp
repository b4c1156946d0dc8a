// Smooth per-vertex values: interior averages, boundary extrapolation, regions, T-vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "core/polygon.h"
#include "viz/vertex_interpolation.h"
#include "viz/viz_test_support.h"

namespace rt::viz {
namespace {

Mesh unitSquareGrid(int n) {
  Scene scene;
  scene.materials.push_back({"white", Rgb(0.5, 0.5, 0.5), Rgb::Zero()});
  scene.materials.push_back({"light", Rgb::Zero(), Rgb(1, 1, 1)});
  scene.surfaces.push_back({"floor", 0});
  Patch p;
  p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  p.normal = Vec3::UnitZ();
  p.area = 1;
  p.surface = 0;
  scene.patches.push_back(p);
  MeshOptions o;
  o.mode = MeshOptions::Mode::Count;
  o.count = n;
  return buildMesh(scene, o);
}

TEST(VertexInterpolation, FlatRepeatsTheElementValue) {
  const Mesh mesh = unitSquareGrid(2);
  RgbField B(4, 3);
  for (int e = 0; e < 4; ++e) B.row(e).setConstant(e);
  const CornerField flat = flatCornerValues(mesh, B);
  ASSERT_EQ(flat.firstCorner.size(), 5u);
  for (int e = 0; e < 4; ++e)
    for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(flat.at(e, k)[0], e);
}

TEST(VertexInterpolation, ConstantFieldStaysConstant) {
  const Mesh mesh = unitSquareGrid(4);
  const RgbField B = RgbField::Constant(16, 3, 2.5);
  const CornerField smooth = smoothCornerValues(mesh, B);
  EXPECT_NEAR((smooth.values.array() - 2.5).abs().maxCoeff(), 0.0, 1e-12);
}

TEST(VertexInterpolation, LinearFieldIsReproducedExactly) {
  // B = x at element centroids: interior averages and boundary extrapolations both give B = x at the
  // vertices.
  const Mesh mesh = unitSquareGrid(4);
  RgbField B(static_cast<Eigen::Index>(mesh.size()), 3);
  for (std::size_t e = 0; e < mesh.size(); ++e) B.row(e).setConstant(1.0 + mesh.elements[e].centroid.x());
  const CornerField smooth = smoothCornerValues(mesh, B);
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (std::size_t k = 0; k < mesh.elements[e].vertices.size(); ++k)
      EXPECT_NEAR(smooth.at(static_cast<int>(e), static_cast<int>(k))[0],
                  1.0 + mesh.vertices[mesh.elements[e].vertices[k]].x(), 1e-12);
}

TEST(VertexInterpolation, MaterialsAndCreasesAreNotAveraged) {
  const Mesh mesh = buildMesh(vizt::openRoom());
  const std::vector<int> regions = smoothRegions(mesh);
  // Six patches, six different planes: six regions.
  EXPECT_EQ(*std::max_element(regions.begin(), regions.end()) + 1, 6);
  RgbField B(static_cast<Eigen::Index>(mesh.size()), 3);
  for (std::size_t e = 0; e < mesh.size(); ++e) B.row(e).setConstant(static_cast<double>(e));
  const CornerField smooth = smoothCornerValues(mesh, B);
  // One element per region: every corner keeps its own element's value (boundary, no interior corner).
  for (std::size_t e = 0; e < mesh.size(); ++e) EXPECT_DOUBLE_EQ(smooth.at(static_cast<int>(e), 0)[0], e);
}

TEST(VertexInterpolation, TVertexTakesTheValueAlongTheLongEdge) {
  // Two coplanar patches of the same material: the left one split 2x2, the right one whole. The vertex (1,
  // 0.5) is a corner of the small elements and lies on the right element's edge.
  Scene scene;
  scene.materials.push_back({"white", Rgb(0.5, 0.5, 0.5), Rgb::Zero()});
  scene.surfaces.push_back({"floor", 0});
  for (double x0 : {0.0, 1.0}) {
    Patch p;
    p.vertices = {{x0, 0, 0}, {x0 + 1, 0, 0}, {x0 + 1, 1, 0}, {x0, 1, 0}};
    p.normal = Vec3::UnitZ();
    p.area = 1;
    p.surface = 0;
    scene.patches.push_back(p);
  }
  const Mesh coarse = buildMesh(scene);
  MeshOptions split;
  split.mode = MeshOptions::Mode::Count;
  split.count = 2;
  const Mesh fine = buildMesh(scene, split);
  // Assemble: the fine elements of patch 0 and the coarse element of patch 1, sharing welded vertices.
  Mesh mesh = fine;
  mesh.elements.clear();
  std::vector<int> keep;
  for (std::size_t e = 0; e < fine.size(); ++e)
    if (fine.elements[e].patch == 0) keep.push_back(static_cast<int>(e));
  for (int e : keep) mesh.elements.push_back(fine.elements[e]);
  Element big = coarse.elements[1];
  for (int& v : big.vertices) {
    const Vec3 p = coarse.vertices[v];
    v = static_cast<int>(std::find_if(mesh.vertices.begin(), mesh.vertices.end(),
                                      [&](const Vec3& q) { return (q - p).norm() < 1e-12; }) -
                         mesh.vertices.begin());
    ASSERT_LT(v, static_cast<int>(mesh.vertices.size()));
  }
  mesh.elements.push_back(big);
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  mesh.reflectance = RgbField::Constant(n, 3, 0.5);
  mesh.emission = RgbField::Zero(n, 3);
  mesh.vertexElements.assign(mesh.vertices.size(), {});
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    for (int v : mesh.elements[e].vertices) mesh.vertexElements[v].push_back(static_cast<int>(e));

  RgbField B(n, 3);
  for (Eigen::Index e = 0; e < n; ++e) B.row(e).setConstant(1.0 + mesh.elements[e].centroid.y());
  const CornerField smooth = smoothCornerValues(mesh, B);
  // Find the T-vertex (1, 0.5) among the small elements' corners and the big element's corners at (1,0) and
  // (1,1).
  auto valueAt = [&](const Vec3& p) {
    for (std::size_t e = 0; e < mesh.elements.size(); ++e)
      for (std::size_t k = 0; k < mesh.elements[e].vertices.size(); ++k)
        if ((mesh.vertices[mesh.elements[e].vertices[k]] - p).norm() < 1e-12)
          return smooth.at(static_cast<int>(e), static_cast<int>(k))[0];
    return -1.0;
  };
  const double bottom = valueAt({1, 0, 0}), topValue = valueAt({1, 1, 0}), middle = valueAt({1, 0.5, 0});
  EXPECT_NEAR(middle, 0.5 * (bottom + topValue), 1e-12);
}

TEST(VertexInterpolation, AStripOneElementWideIsNotExtrapolatedAcross) {
  // Eight elements in a row (a door jamb), their corners off the straight lines by file rounding (1e-7 of
  // their 0.125 m): the least-squares gradient across the strip is undetermined and must not be taken from
  // the rounding.
  Mesh mesh;
  for (int i = 0; i <= 8; ++i)
    for (double y : {0.0, 0.125}) mesh.vertices.push_back({0.125 * i, y + 1e-7 * std::sin(7.0 * i + y), 0});
  for (int i = 0; i < 8; ++i) {
    Element e;
    e.vertices = {2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1};
    e.patch = 0;
    e.normal = Vec3::UnitZ();
    e.area = 0.125 * 0.125;
    e.centroid = Vec3::Zero();
    for (int v : e.vertices) e.centroid += mesh.vertices[v] / 4.0;
    mesh.elements.push_back(e);
  }
  mesh.vertexElements.assign(mesh.vertices.size(), {});
  for (std::size_t e = 0; e < mesh.size(); ++e)
    for (int v : mesh.elements[e].vertices) mesh.vertexElements[v].push_back(static_cast<int>(e));
  mesh.reflectance = RgbField::Constant(8, 3, 0.5);
  mesh.emission = RgbField::Zero(8, 3);
  RgbField B(8, 3);
  for (int e = 0; e < 8; ++e) B.row(e).setConstant(1.0 + 0.3 * (e % 2));  // noisy, as a solution is
  const CornerField smooth = smoothCornerValues(mesh, B);
  // The corners stay near the values around them (the rounding's gradient would put them at 1e5).
  EXPECT_LT(smooth.values.maxCoeff(), 2.0);
  EXPECT_GT(smooth.values.minCoeff(), 0.3);
}

TEST(VertexInterpolation, AKeptStructureGivesTheSameValuesForEveryField) {
  // The app finds the structure once per mesh and applies it to every iteration of the replay.
  const Mesh mesh = buildMesh(vizt::openRoom(), [] {
    MeshOptions o;
    o.mode = MeshOptions::Mode::Count;
    o.count = 5;
    return o;
  }());
  const SmoothInterpolation kept(mesh);
  EXPECT_EQ(kept.elements(), mesh.size());
  for (int field = 0; field < 3; ++field) {
    RgbField B(static_cast<Eigen::Index>(mesh.size()), 3);
    for (Eigen::Index e = 0; e < B.rows(); ++e)
      B.row(e) << 1 + std::sin(0.3 * e + field), 0.5 + 0.01 * e, field == 2 ? -0.2 * (e % 3) : 0.7;
    const CornerField direct = smoothCornerValues(mesh, B);
    const CornerField applied = kept.apply(B);
    EXPECT_EQ(applied.firstCorner, direct.firstCorner);
    EXPECT_LT((applied.values - direct.values).cwiseAbs().maxCoeff(), 1e-12);
  }
}

}  // namespace
}  // namespace rt::viz
