// Near-coplanar overlaps: a patch parallel to another and a little in front of it (a light hung below an
// uncut ceiling) covers part of it, and the mesh cuts the covered patch along the front patch's outline, so
// that the covered part, which sees only the front patch's back, is made of elements of its own.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/contact_lines.h"
#include "core/formfactor/formfactor_method.h"
#include "core/io/scene_loader.h"
#include "core/mesh.h"
#include "core/polygon.h"
#include "core/progress.h"
#include "formfactor_scenes.h"
#include "support/test_paths.h"

namespace rt {
namespace {

using test::patchOf;

double sceneDiagonal(const Scene& scene) {
  return scene.bounds().diagonal().norm();
}

// The default tolerances of buildMesh: 1e-7 of the diagonal for "in the plane", the default gap.
std::vector<CutSegment> defaultCuts(const Scene& scene, int patch) {
  const double size = sceneDiagonal(scene);
  return cutSegments(scene, patch, 1e-7 * size, MeshOptions{}.overlapGap * size);
}
std::vector<Polygon> defaultPieces(const Scene& scene, int patch) {
  const double size = sceneDiagonal(scene);
  return cutAtContacts(scene, patch, 1e-7 * size, MeshOptions{}.overlapGap * size);
}

// The pieces tile the patch (area kept), each convex and facing the patch's way.
void expectTiling(const Scene& scene, int patch, const std::vector<Polygon>& pieces) {
  const Patch& p = scene.patches[static_cast<std::size_t>(patch)];
  double area = 0;
  for (const Polygon& piece : pieces) {
    area += polygonArea(piece);
    EXPECT_TRUE(isConvex(piece, p.normal));
    EXPECT_GT(newellNormal(piece).normalized().dot(p.normal), 0.999);
  }
  EXPECT_NEAR(area, p.area, 1e-9 * p.area);
}

// Strictly inside a convex polygon (CCW about `normal`) by more than `margin`, or strictly outside.
int side(const Polygon& outline, const Vec3& normal, const Vec3& point, double margin) {
  bool onEdge = false;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const Vec3 inward = normal.cross(outline[(k + 1) % outline.size()] - outline[k]).normalized();
    const double d = (point - outline[k]).dot(inward);
    if (d < -margin) return -1;
    if (d <= margin) onEdge = true;
  }
  return onEdge ? 0 : 1;
}

// The area of the pieces lying under `front` (projected along the patch's normal).
double coveredArea(const Scene& scene, int patch, const std::vector<Polygon>& pieces, const Polygon& front) {
  const Patch& p = scene.patches[static_cast<std::size_t>(patch)];
  Polygon outline;
  for (const Vec3& v : front) outline.push_back(v - (v - p.vertices.front()).dot(p.normal) * p.normal);
  double area = 0;
  for (const Polygon& piece : pieces)
    if (side(outline, p.normal, polygonCentroid(piece), 0) > 0) area += polygonArea(piece);
  return area;
}

void checkCeilingCut(const char* file, double gap) {
  const Scene scene = loadScene(test::sourcePath(std::string("scenes/") + file));
  const int ceiling = patchOf(scene, "ceiling"), light = patchOf(scene, "light");
  ASSERT_GE(ceiling, 0);
  const std::vector<CutSegment> segments = defaultCuts(scene, ceiling);
  ASSERT_EQ(segments.size(), 4u);
  for (const CutSegment& s : segments) {
    EXPECT_TRUE(s.overlap);
    EXPECT_EQ(s.other, light);
    EXPECT_NEAR(s.gap, gap, 1e-9);
    EXPECT_NEAR(s.a.y(), 548.8, 1e-9);  // in the ceiling's plane
  }
  const std::vector<Polygon> pieces = defaultPieces(scene, ceiling);
  // The first of the light's edge lines cuts the ceiling in two, the parallel one cuts a half again, and the
  // other two cut the strip between them: the part under the light is one piece of five.
  EXPECT_EQ(pieces.size(), 5u);
  expectTiling(scene, ceiling, pieces);
  const Patch& l = scene.patches[static_cast<std::size_t>(light)];
  EXPECT_NEAR(coveredArea(scene, ceiling, pieces, l.vertices), l.area, 1e-9 * l.area);
  // Nothing else is cut by the overlap: the light itself lies in front of nothing.
  for (const CutSegment& s : defaultCuts(scene, light)) ADD_FAILURE() << "light cut by patch " << s.other;
}

TEST(OverlapCuts, ALightOneCentimetreBelowTheCeilingCutsItAlongItsOutline) {
  checkCeilingCut("cornell-box-closed-light-1cm.json", 10);
}

TEST(OverlapCuts, ALightATenthOfAMillimetreBelowTheCeilingCutsItAlongItsOutline) {
  checkCeilingCut("cornell-box-closed-light-0.1mm.json", 0.1);
}

TEST(OverlapCuts, TheFlushLightOfTheClosedBoxCutsNothing) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box-closed.json"));
  for (const MeshCut& cut : meshCuts(scene, defaultMeshOptions(scene))) EXPECT_FALSE(cut.overlap);
}

// A square wall, tilted about an axis that is no coordinate axis, with a smaller square "picture" 1 % of the
// diagonal in front of it, turned by 30 degrees in its plane; `shift` moves the picture within the plane.
Scene tiltedWallWithPicture(double gapFraction, const Vec2& shift, double tiltDegrees = 0,
                            double turnDegrees = 30) {
  Scene s = test::emptyScene();
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();  // the whole pair
  auto place = [&](double x, double y, double z) { return Vec3(turn * Vec3(x, y, z)); };
  test::addQuad(s, place(0, 0, 0), place(2, 0, 0), place(2, 2, 0), place(0, 2, 0));  // the wall, facing +z
  const double diagonal = std::sqrt(8.0);  // the scene's size is about the wall's
  constexpr double kPi = std::numbers::pi;
  const double gap = gapFraction * diagonal, angle = turnDegrees * kPi / 180, tilt = tiltDegrees * kPi / 180;
  std::vector<Vec2> corners;
  for (int k = 0; k < 4; ++k) {
    const double a = angle + k * kPi / 2;
    corners.push_back(Vec2(1, 1) + shift + 0.5 * Vec2(std::cos(a), std::sin(a)));
  }
  // Tilted about the line through its lowest corner: its height above the wall grows along x from `gap`.
  double lowest = corners[0].x();
  for (const Vec2& c : corners) lowest = std::min(lowest, c.x());
  Polygon picture;
  for (const Vec2& c : corners)
    picture.push_back(place(c.x(), c.y(), gap + std::tan(tilt) * (c.x() - lowest)));
  test::addQuad(s, picture[0], picture[1], picture[2], picture[3], true);
  return s;
}

TEST(OverlapCuts, ARotatedPairIsCutAlongThePicturesOutline) {
  const Scene scene = tiltedWallWithPicture(0.01, Vec2::Zero());
  const std::vector<CutSegment> segments = defaultCuts(scene, 0);
  ASSERT_EQ(segments.size(), 4u);
  for (const CutSegment& s : segments) EXPECT_TRUE(s.overlap);
  const std::vector<Polygon> pieces = defaultPieces(scene, 0);
  expectTiling(scene, 0, pieces);
  EXPECT_NEAR(coveredArea(scene, 0, pieces, scene.patches[1].vertices), scene.patches[1].area, 1e-9);
  // The picture itself is not cut (the wall lies behind it), and no element of the default mesh straddles
  // the picture's outline.
  EXPECT_TRUE(defaultCuts(scene, 1).empty());
  MeshOptions options;
  options.mode = MeshOptions::Mode::MaxEdge;
  options.maxEdge = 0.3;
  options.splitAtContacts = true;
  const Mesh mesh = buildMesh(scene, options);
  Polygon outline;
  for (const Vec3& v : scene.patches[1].vertices)
    outline.push_back(v - (v - scene.patches[0].vertices.front()).dot(scene.patches[0].normal) *
                              scene.patches[0].normal);
  int straddling = 0, under = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (mesh.elements[e].patch != 0) continue;
    bool in = false, out = false;
    for (const Vec3& v : mesh.polygon(static_cast<int>(e))) {
      const int s = side(outline, scene.patches[0].normal, v, 1e-9);
      in = in || s > 0;
      out = out || s < 0;
    }
    straddling += in && out;
    under += in && !out;
  }
  EXPECT_EQ(straddling, 0);
  EXPECT_GT(under, 0);
}

TEST(OverlapCuts, APictureHangingOverTheWallsEdgeCutsOnlyWhereItCovers) {
  // The picture's centre 0.9 from the wall's centre along x: part of it hangs beyond the wall's edge x = 2.
  // Turned by 45 degrees its edges are the wall's axes, so that the covered part is a rectangle.
  const Scene scene = tiltedWallWithPicture(0.01, Vec2(0.9, 0.2), 0, 45);
  const std::vector<CutSegment> segments = defaultCuts(scene, 0);
  EXPECT_EQ(segments.size(), 3u);  // the edge beyond the wall's edge cuts nothing
  const std::vector<Polygon> pieces = defaultPieces(scene, 0);
  expectTiling(scene, 0, pieces);
  // The covered pieces add up to the part of the picture over the wall: a square of side 2 half, from
  // x = 1.9 - half to the wall's edge.
  const double half = 0.5 * std::sqrt(0.5);
  const double expected = (2 - (1.9 - half)) * 2 * half;
  EXPECT_LT(expected, 0.9 * scene.patches[1].area);
  EXPECT_NEAR(coveredArea(scene, 0, pieces, scene.patches[1].vertices), expected, 1e-9);
}

TEST(OverlapCuts, TooFarTiltedOrBehindIsNotCut) {
  // 5 % of the diagonal in front: beyond the default gap of 2 %.
  EXPECT_TRUE(defaultCuts(tiltedWallWithPicture(0.05, Vec2::Zero()), 0).empty());
  // Tilted by 3 degrees (not parallel): not cut, even by a gap that reaches all of it.
  const Scene tilted = tiltedWallWithPicture(0.01, Vec2::Zero(), 3);
  EXPECT_TRUE(cutSegments(tilted, 0, 1e-7 * sceneDiagonal(tilted), 0.2 * sceneDiagonal(tilted)).empty());
  // Behind the wall.
  EXPECT_TRUE(defaultCuts(tiltedWallWithPicture(-0.01, Vec2::Zero()), 0).empty());
  // An overlap gap of 0 turns the cut off; a larger one catches the far picture.
  const Scene far = tiltedWallWithPicture(0.05, Vec2::Zero());
  const double size = sceneDiagonal(far);
  EXPECT_TRUE(cutSegments(tiltedWallWithPicture(0.01, Vec2::Zero()), 0, 1e-7 * size, 0).empty());
  EXPECT_EQ(cutSegments(far, 0, 1e-7 * size, 0.06 * size).size(), 4u);
}

// What a reader is told: the mesh's cuts, by surface, each with its kind.
TEST(OverlapCuts, TheCutsAreReportedBySurface) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box-closed-light-0.1mm.json"));
  const std::vector<MeshCut> cuts = meshCuts(scene, defaultMeshOptions(scene));
  const std::vector<std::string> lines = describeMeshCuts(scene, cuts);
  ASSERT_EQ(lines.size(), cuts.size());
  int overlaps = 0, contacts = 0;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    overlaps += cuts[k].overlap;
    contacts += !cuts[k].overlap;
    if (cuts[k].overlap) {
      EXPECT_EQ(lines[k],
                "ceiling (patch 2) along the outline of light, 0.1 mm in front of it (overlap): 4 segments");
    }
  }
  EXPECT_EQ(overlaps, 1);
  EXPECT_EQ(contacts, 2);  // the floor, where each block stands on it
}

// The default mesh of the scene with the light 0.1 mm below the ceiling: no ceiling element straddles the
// light's outline, and the closed box's rows of F still sum to 1 (the covered ceiling, which sees only the
// light's back, excepted).
TEST(OverlapCuts, DefaultSolveMeshOfTheNearCeilingLightScene) {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell-box-closed-light-0.1mm.json"));
  const int ceiling = patchOf(scene, "ceiling"), light = patchOf(scene, "light"),
            floor = patchOf(scene, "floor");
  const MeshOptions options = defaultMeshOptions(scene);
  const Mesh mesh = buildMesh(scene, options);
  const Patch& l = scene.patches[static_cast<std::size_t>(light)];
  Polygon outline;
  for (const Vec3& v : l.vertices) outline.emplace_back(v.x(), 548.8, v.z());
  const Vec3 down(0, -1, 0);
  std::vector<char> covered(mesh.size(), 0);
  int straddling = 0, under = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (mesh.elements[e].patch != ceiling) continue;
    bool in = false, out = false;
    for (const Vec3& v : mesh.polygon(static_cast<int>(e))) {
      const int s = side(outline, down, v, 1e-6);
      in = in || s > 0;
      out = out || s < 0;
    }
    straddling += in && out;
    under += in && !out;
    covered[e] = in && !out;
  }
  EXPECT_EQ(straddling, 0);
  EXPECT_GT(under, 0);

  FormFactorStats stats;
  const FormFactorMatrix F =
      makeFormFactorMethod(defaultFormFactorMethod())->compute(mesh, {}, noProgress(), stats);
  double worst = 0, coveredMost = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const double sum = F.row(static_cast<Eigen::Index>(e)).sum();
    if (covered[e])
      coveredMost = std::max(coveredMost, sum);
    else if (!(mesh.elements[e].patch == floor && sum == 0))  // the floor under a block sees its inside
      worst = std::max(worst, std::abs(sum - 1));
  }
  EXPECT_LT(worst, 2e-3);
  EXPECT_LT(coveredMost, 0.05);  // 0.1 mm of slit to the room at most
}

}  // namespace
}  // namespace rt
