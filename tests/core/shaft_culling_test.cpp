// The shaft test against the rule it implements, checked by brute force over every patch, on rooms whose
// walls are given as many separate faces (where a test of every patch for every patch pair made the setup
// cubic: 25 s at 2,400 faces, half an hour at 9,600).
#include <gtest/gtest.h>

#include <random>

#include "core/formfactor/shaft_culling.h"
#include "formfactor_scenes.h"

namespace rt {
namespace {

// A closed room [0,1]^3 whose six walls are split into n x n separate quads (inward), with a block standing
// on the floor (outward, without its bottom).
Scene gridRoom(int n) {
  Scene s = test::emptyScene();
  for (int axis = 0; axis < 3; ++axis)
    for (double at : {0.0, 1.0}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          Vec3 p[4];
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int c = 0; c < 4; ++c) {
            p[c][axis] = at;
            p[c][u] = double(a + du[c]) / n;
            p[c][v] = double(b + dv[c]) / n;
          }
          // (u, v, axis) is right-handed, so this order faces +axis: inward at 0, reversed at 1.
          if (at == 0)
            test::addQuad(s, p[0], p[1], p[2], p[3]);
          else
            test::addQuad(s, p[3], p[2], p[1], p[0]);
        }
    }
  test::addBox(s, Vec3(0.3, 0.3, 0), Vec3(0.6, 0.7, 0.45), true);
  s.patches.erase(s.patches.begin() + static_cast<long>(6 * n * n));  // the block's bottom lies on the floor
  return s;
}

enum Side : std::uint8_t { kFront = 1, kBack = 2, kBoth = 3 };

std::uint8_t sideOf(const std::vector<Vec3>& points, const Element& plane, const Mesh& mesh, double eps) {
  std::uint8_t side = 0;
  const Vec3 origin = mesh.vertices[static_cast<std::size_t>(plane.vertices[0])];
  for (const Vec3& p : points) {
    const double d = plane.normal.dot(p - origin);
    if (d > eps) side |= kFront;
    if (d < -eps) side |= kBack;
  }
  return side;
}

std::vector<Vec3> pointsOf(const Mesh& mesh, int e) {
  std::vector<Vec3> out;
  for (int v : mesh.elements[static_cast<std::size_t>(e)].vertices)
    out.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
  return out;
}

Eigen::AlignedBox3d boxOf(const std::vector<Vec3>& points) {
  Eigen::AlignedBox3d box;
  for (const Vec3& p : points) box.extend(p);
  return box;
}

bool strictlyOverlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double eps) {
  return (a.min().array() < b.max().array() - eps).all() && (b.min().array() < a.max().array() - eps).all();
}

// The rule, with one element per patch: some k other than i and j overlaps their box, reaches in front of
// both their planes, and has i and j strictly on both sides of its own plane.
bool occludableByBruteForce(const Mesh& mesh, int i, int j, double eps) {
  const auto pi = pointsOf(mesh, i), pj = pointsOf(mesh, j);
  Eigen::AlignedBox3d shaft = boxOf(pi);
  shaft.extend(boxOf(pj));
  for (int k = 0; k < static_cast<int>(mesh.size()); ++k) {
    if (k == i || k == j) continue;
    const auto pk = pointsOf(mesh, k);
    if (!strictlyOverlap(shaft, boxOf(pk), eps)) continue;
    const Element& ei = mesh.elements[static_cast<std::size_t>(i)];
    const Element& ej = mesh.elements[static_cast<std::size_t>(j)];
    const Element& ek = mesh.elements[static_cast<std::size_t>(k)];
    if (!(sideOf(pk, ei, mesh, eps) & kFront) || !(sideOf(pk, ej, mesh, eps) & kFront)) continue;
    if (((sideOf(pi, ek, mesh, eps) | sideOf(pj, ek, mesh, eps)) & kBoth) == kBoth) return true;
  }
  return false;
}

TEST(ShaftCulling, SeparateFacesAgreeWithTheRuleAndScale) {
  // 6 * 40^2 + 5 = 9,605 faces: the set-up used to test every patch against every patch pair (10^12 tests).
  const Mesh mesh = test::meshOf(gridRoom(40), 1);
  ASSERT_EQ(mesh.size(), 9605u);
  const ShaftCulling shafts(mesh);
  EXPECT_TRUE(shafts.anyOccluder());
  std::mt19937 random(7);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(mesh.size()) - 1);
  int occludable = 0;
  for (int sample = 0; sample < 3000; ++sample) {
    const int i = pick(random), j = pick(random);
    if (i == j) continue;
    const bool expected = occludableByBruteForce(mesh, i, j, 1e-9 * std::sqrt(3.0));
    ASSERT_EQ(shafts.mayBeOccluded(i, j), expected) << i << " " << j;
    occludable += expected;
  }
  EXPECT_GT(occludable, 100);  // the block stands in the way of many pairs: the sample tests both answers
}

TEST(ShaftCulling, SubdividedPatchesUseTheirPatchPairsAndAgree) {
  // Few patches, several elements each: the patch pairs' candidates are tabulated; the answers are the same
  // as for the rule applied to the elements directly.
  const Mesh mesh = test::meshOf(gridRoom(2), 3);
  const ShaftCulling shafts(mesh);
  for (int i = 0; i < static_cast<int>(mesh.size()); i += 3)
    for (int j = 0; j < static_cast<int>(mesh.size()); j += 2) {
      if (mesh.elements[static_cast<std::size_t>(i)].patch ==
          mesh.elements[static_cast<std::size_t>(j)].patch)
        continue;
      // Whole patches as blockers: the brute force over elements finds a blocker whenever one of the
      // blocker's patch's elements qualifies, so compare the answer's monotone part: occluded by the rule
      // over elements implies occludable here.
      if (occludableByBruteForce(mesh, i, j, 1e-9 * std::sqrt(3.0))) {
        EXPECT_TRUE(shafts.mayBeOccluded(i, j)) << i << " " << j;
      }
    }
}

// A wall of the room has the whole scene in front of its plane: it can never stand between two elements, so
// it is never a candidate (the box tree holds only the faces of the block, so it is not even visited).
TEST(ShaftCulling, OnlyTheBlocksFacesAreEverCandidates) {
  constexpr int n = 10;
  const Mesh mesh = test::meshOf(gridRoom(n), 1);
  const ShaftCulling shafts(mesh);
  std::vector<int> candidates;
  int pairs = 0;
  for (int i = 0; i < static_cast<int>(mesh.size()); i += 3)
    for (int j = 1; j < static_cast<int>(mesh.size()); j += 4) {
      candidates.clear();
      shafts.candidates(i, j, candidates);
      pairs += !candidates.empty();
      for (int k : candidates) EXPECT_GE(k, 6 * n * n) << i << " " << j;
    }
  EXPECT_GT(pairs, 100);
}

TEST(ShaftCulling, AConvexRoomHasNoOccluder) {
  Scene room = gridRoom(6);
  room.patches.resize(6 * 36);  // without the block
  const Mesh mesh = test::meshOf(room, 1);
  const ShaftCulling shafts(mesh);
  EXPECT_FALSE(shafts.anyOccluder());
  for (int i = 0; i < static_cast<int>(mesh.size()); i += 7)
    for (int j = 0; j < static_cast<int>(mesh.size()); j += 5) EXPECT_FALSE(shafts.mayBeOccluded(i, j));
}

// A patch's outline is its corners, however finely it is meshed: the elements' vertices along its edges are
// on them only to rounding, and outlines that kept some did not share edges with their neighbours (the
// Cornell box's tall block at --max-edge 50 was then no closed solid).
TEST(ShaftCulling, FinelyMeshedPatchesKeepTheirCornersOnly) {
  for (int subdivide : {1, 3, 7, 10, 24}) {
    const Mesh mesh = test::meshOf(test::roomWithBlock(), subdivide);
    const ShaftCulling shafts(mesh);
    for (std::size_t k = 0; k < shafts.patchCount(); ++k)
      EXPECT_EQ(shafts.outline(static_cast<int>(k)).size(), 4u)
          << "patch " << k << ", " << subdivide << " a side";
  }
}

}  // namespace
}  // namespace rt
