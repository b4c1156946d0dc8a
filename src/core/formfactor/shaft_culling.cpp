#include "core/formfactor/shaft_culling.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "core/parallel.h"

namespace rt {
namespace {

// Patch pairs are tabulated when there are at most this many patches (the table holds P^2 / 2 lists) and
// patches have at least two elements on average (otherwise the table is as much work as the pairs
// themselves).
constexpr std::size_t kMaxTabulatedPatches = 4096;
// Patch-against-plane tests spent on finding which patches can block at all (a million separate faces in
// distinct planes would otherwise cost a million squared).
constexpr long kMaxPlaneTests = 20'000'000;
// Entries of the blockers' side tables (a byte each): (patches + elements) x blockers.
constexpr std::size_t kMaxSideTable = 16'000'000;

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

// The extreme points of planar points: Andrew's monotone chain in the plane's own 2D coordinates. A linear
// function takes its minimum and maximum over the patch at these, so sides need only them.
std::vector<Vec3> convexOutline(std::vector<Vec3> points, const Vec3& normal) {
  if (points.size() <= 3) return points;
  const Vec3 u = normal.unitOrthogonal(), v = normal.normalized().cross(u);
  std::vector<std::pair<Eigen::Vector2d, int>> flat;
  for (std::size_t k = 0; k < points.size(); ++k)
    flat.push_back({{points[k].dot(u), points[k].dot(v)}, static_cast<int>(k)});
  std::sort(flat.begin(), flat.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.x(), a.first.y()) < std::tie(b.first.x(), b.first.y());
  });
  std::vector<std::pair<Eigen::Vector2d, int>> hull(2 * flat.size());
  std::size_t h = 0;
  for (std::size_t k = 0; k < flat.size(); ++k) {
    while (h >= 2 && cross2(hull[h - 2].first, hull[h - 1].first, flat[k].first) <= 0) --h;
    hull[h++] = flat[k];
  }
  for (std::size_t k = flat.size() - 1, lower = h + 1; k-- > 0;) {
    while (h >= lower && cross2(hull[h - 2].first, hull[h - 1].first, flat[k].first) <= 0) --h;
    hull[h++] = flat[k];
  }
  hull.resize(h - 1);
  // The elements' vertices along a patch's edge are on it only to rounding: some stick out by 1e-17 and are
  // corners of the exact hull. Dropped, round the closed outline, where a corner lies between its neighbours
  // on their line to rounding: an outline that kept some would not share its edges with the next face's (a
  // block of finely meshed faces would be no closed solid).
  Eigen::AlignedBox2d extent;
  for (const auto& [p, index] : flat) extent.extend(p);
  const double straight = 1e-12 * extent.diagonal().squaredNorm();
  for (bool dropped = true; dropped && hull.size() > 3;) {
    dropped = false;
    for (std::size_t k = 0; k < hull.size() && hull.size() > 3; ++k) {
      const Eigen::Vector2d &a = hull[(k + hull.size() - 1) % hull.size()].first, &p = hull[k].first,
                            &b = hull[(k + 1) % hull.size()].first;
      const double along = (p - a).dot(b - a);
      if (std::abs(cross2(a, p, b)) <= straight && along > 0 && along < (b - a).squaredNorm()) {
        hull.erase(hull.begin() + static_cast<std::ptrdiff_t>(k));
        dropped = true;
      }
    }
  }
  std::vector<Vec3> out;
  for (const auto& [p, index] : hull) out.push_back(points[static_cast<std::size_t>(index)]);
  return out.size() >= 3 ? out : points;
}

}  // namespace

ShaftCulling::ShaftCulling(const Mesh& mesh) : mesh_(mesh) {
  int maxPatch = -1;
  for (const Element& e : mesh.elements) maxPatch = std::max(maxPatch, e.patch);
  patchCount_ = static_cast<std::size_t>(maxPatch + 1);
  const std::size_t P = patchCount_, n = mesh.elements.size();
  patches_.assign(P, {});
  Eigen::AlignedBox3d all;
  for (const Vec3& v : mesh.vertices) all.extend(v);
  eps_ = 1e-9 * (all.isEmpty() ? 1.0 : all.diagonal().norm());

  elementBoxes_.resize(n);
  elementPatch_.resize(n);
  std::vector<std::vector<int>> patchVertices(P);
  for (std::size_t e = 0; e < n; ++e) {
    const Element& element = mesh.elements[e];
    for (int v : element.vertices) elementBoxes_[e].extend(mesh.vertices[v]);
    elementPatch_[e] = element.patch;
    PatchInfo& patch = patches_[element.patch];
    if (patch.box.isEmpty()) {
      patch.normal = element.normal;
      patch.point = mesh.vertices[element.vertices[0]];
    }
    patch.box.extend(elementBoxes_[e]);
    patchVertices[element.patch].insert(patchVertices[element.patch].end(), element.vertices.begin(),
                                        element.vertices.end());
  }
  for (std::size_t k = 0; k < P; ++k) {
    auto& ids = patchVertices[k];
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<Vec3> points;
    for (int v : ids) points.push_back(mesh.vertices[v]);
    patches_[k].outline = convexOutline(std::move(points), patches_[k].normal);
  }
  // Only a patch with something strictly behind its plane can ever block (test (3) needs the two ends on
  // opposite sides); a room's walls cannot, and they are most of its patches. Patches in one plane (a wall
  // split into quads) are tested once; a plane with the scene's box on its front needs no test at all.
  Eigen::AlignedBox3d sceneBox;
  for (const PatchInfo& p : patches_) sceneBox.extend(p.box);
  std::map<std::tuple<long long, long long, long long, long long>, bool> planes;
  long budget = kMaxPlaneTests;
  for (std::size_t k = 0; k < P; ++k) {
    if (patches_[k].box.isEmpty()) continue;
    const Vec3& nk = patches_[k].normal;
    const double scale = 1e6 / (all.isEmpty() ? 1.0 : all.diagonal().norm());
    const auto key =
        std::make_tuple(std::llround(nk.x() * 1e9), std::llround(nk.y() * 1e9), std::llround(nk.z() * 1e9),
                        std::llround(nk.dot(patches_[k].point) * scale));
    auto [it, added] = planes.emplace(key, false);
    if (added) {
      bool behind = false;
      for (int c = 0; c < 8 && !behind; ++c)
        behind = nk.dot(sceneBox.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) -
                        patches_[k].point) < -eps_;
      // The box reaches behind: look for a patch that does, within a bounded number of tests (past it,
      // planes count as blocking, which costs time, never correctness).
      if (behind && budget > 0) {
        behind = false;
        for (std::size_t other = 0; other < P && !behind; ++other, --budget)
          behind = sideOfPatch(static_cast<int>(other), static_cast<int>(k)) & kBack;
      }
      it->second = behind;
    }
    if (it->second) blockers_.push_back(static_cast<int>(k));
  }
  anyOccluder_ = !blockers_.empty();
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int k : blockers_) boxes.push_back(patches_[static_cast<std::size_t>(k)].box);
  tree_ = BoxTree(std::move(boxes));
  // Every pair asks the same few sides of the same few blockers: tabulated when the tables are small.
  const std::size_t B = blockers_.size();
  if (B > 0 && (P + n) * B <= kMaxSideTable) {
    blockerIndex_.assign(P, -1);
    for (std::size_t t = 0; t < B; ++t)
      blockerIndex_[static_cast<std::size_t>(blockers_[t])] = static_cast<int>(t);
    patchSides_.resize(P * B);
    elementSides_.resize(n * B);
    parallelFor(std::size_t(0), P, [&](std::size_t a) {
      for (std::size_t t = 0; t < B; ++t)
        patchSides_[a * B + t] =
            static_cast<std::uint8_t>(sideOfPatch(blockers_[t], static_cast<int>(a)) |
                                      sideOfPatch(static_cast<int>(a), blockers_[t]) << 2);
    });
    parallelFor(std::size_t(0), n, [&](std::size_t e) {
      for (std::size_t t = 0; t < B; ++t)
        elementSides_[e * B + t] = sideOfElement(static_cast<int>(e), blockers_[t]);
    });
  }

  if (anyOccluder_ && P <= kMaxTabulatedPatches && n >= 2 * P) {
    pairCandidates_.assign(P * P, {});
    parallelFor(std::size_t(0), P, [&](std::size_t a) {
      for (std::size_t b = a + 1; b < P; ++b)
        pairCandidates_[a * P + b] = patchPairCandidates(static_cast<int>(a), static_cast<int>(b));
    });
  }
}

std::uint8_t ShaftCulling::sideOfPatch(int k, int plane) const {
  const PatchInfo& p = patches_[static_cast<std::size_t>(plane)];
  std::uint8_t side = kOn;
  for (const Vec3& v : patches_[static_cast<std::size_t>(k)].outline) {
    const double d = p.normal.dot(v - p.point);
    if (d > eps_) side |= kFront;
    if (d < -eps_) side |= kBack;
  }
  return side;
}

std::uint8_t ShaftCulling::sideOfElement(int e, int plane) const {
  const PatchInfo& p = patches_[static_cast<std::size_t>(plane)];
  std::uint8_t side = kOn;
  for (int v : mesh_.elements[static_cast<std::size_t>(e)].vertices) {
    const double d = p.normal.dot(mesh_.vertices[static_cast<std::size_t>(v)] - p.point);
    if (d > eps_) side |= kFront;
    if (d < -eps_) side |= kBack;
  }
  return side;
}

bool ShaftCulling::patchMayBlock(int k, int a, int b) const {
  if (k == a || k == b) return false;
  if (!patchSides_.empty()) {
    const std::size_t B = blockers_.size(),
                      t = static_cast<std::size_t>(blockerIndex_[static_cast<std::size_t>(k)]);
    const std::uint8_t sa = patchSides_[static_cast<std::size_t>(a) * B + t],
                       sb = patchSides_[static_cast<std::size_t>(b) * B + t];
    if (!(sa & kFront) || !(sb & kFront)) return false;
    return (((sa >> 2) | (sb >> 2)) & kBoth) == kBoth;
  }
  if (!(sideOfPatch(k, a) & kFront) || !(sideOfPatch(k, b) & kFront)) return false;
  // Never both strictly in front of k's plane and strictly behind it: k cannot separate them.
  return ((sideOfPatch(a, k) | sideOfPatch(b, k)) & kBoth) == kBoth;
}

std::uint8_t ShaftCulling::elementSide(int e, int k) const {
  if (elementSides_.empty()) return sideOfElement(e, k);
  return elementSides_[static_cast<std::size_t>(e) * blockers_.size() +
                       static_cast<std::size_t>(blockerIndex_[static_cast<std::size_t>(k)])];
}

std::vector<int> ShaftCulling::patchPairCandidates(int a, int b) const {
  Eigen::AlignedBox3d shaft = patches_[static_cast<std::size_t>(a)].box;
  shaft.extend(patches_[static_cast<std::size_t>(b)].box);
  std::vector<int> out;
  tree_.anyOverlapping(shaft, eps_, [&](int t) {
    const int k = blockers_[static_cast<std::size_t>(t)];
    if (patchMayBlock(k, a, b)) out.push_back(k);
    return false;
  });
  return out;
}

template <class Visit>
bool ShaftCulling::visitBlockers(int i, int j, Visit&& visit) const {
  if (!anyOccluder_) return false;
  const int a = elementPatch_[static_cast<std::size_t>(i)], b = elementPatch_[static_cast<std::size_t>(j)];
  if (a == b) return false;  // one planar patch: its elements cannot see each other at all
  Eigen::AlignedBox3d shaft = elementBoxes_[static_cast<std::size_t>(i)];
  shaft.extend(elementBoxes_[static_cast<std::size_t>(j)]);
  // The element-level form of (1) and (3) for a patch that passed the patch-level test.
  auto blocks = [&](int k) {
    if (!BoxTree::overlaps(shaft, patches_[static_cast<std::size_t>(k)].box, eps_)) return false;
    return ((elementSide(i, k) | elementSide(j, k)) & kBoth) == kBoth;
  };
  if (!pairCandidates_.empty()) {
    for (int k : pairCandidates_[static_cast<std::size_t>(std::min(a, b)) * patchCount_ +
                                 static_cast<std::size_t>(std::max(a, b))])
      if (blocks(k) && visit(k)) return true;
    return false;
  }
  return tree_.anyOverlapping(shaft, eps_, [&](int t) {
    const int k = blockers_[static_cast<std::size_t>(t)];
    return patchMayBlock(k, a, b) && blocks(k) && visit(k);
  });
}

void ShaftCulling::candidates(int i, int j, std::vector<int>& patches) const {
  visitBlockers(i, j, [&](int k) {
    patches.push_back(k);
    return false;
  });
}

bool ShaftCulling::mayBeOccluded(int i, int j) const {
  return visitBlockers(i, j, [](int) { return true; });
}

template <class Visit>
bool ShaftCulling::visitPointBlockers(const Vec3& point, const Vec3& normal, int pointPatch, int j,
                                      Visit&& visit) const {
  if (!anyOccluder_) return false;
  const int b = elementPatch_[static_cast<std::size_t>(j)];
  Eigen::AlignedBox3d shaft = elementBoxes_[static_cast<std::size_t>(j)];
  shaft.extend(point);
  return tree_.anyOverlapping(shaft, eps_, [&](int t) {
    const int k = blockers_[static_cast<std::size_t>(t)];
    if (k == b || k == pointPatch) return false;
    // (2): k reaches in front of j's plane and in front of the point's tangent plane.
    if (!(sideOfPatch(k, b) & kFront)) return false;
    const auto& outline = patches_[static_cast<std::size_t>(k)].outline;
    if (std::none_of(outline.begin(), outline.end(),
                     [&](const Vec3& v) { return normal.dot(v - point) > eps_; }))
      return false;
    // (3): k's plane has the point strictly on one side and part of j strictly on the other.
    const PatchInfo& p = patches_[static_cast<std::size_t>(k)];
    const double d = p.normal.dot(point - p.point);
    const std::uint8_t pointSide = d > eps_ ? kFront : d < -eps_ ? kBack : kOn;
    return ((pointSide | elementSide(j, k)) & kBoth) == kBoth && visit(k);
  });
}

bool ShaftCulling::mayBeOccluded(const Vec3& point, const Vec3& normal, int pointPatch, int j) const {
  return visitPointBlockers(point, normal, pointPatch, j, [](int) { return true; });
}

void ShaftCulling::candidates(const Vec3& point, const Vec3& normal, int pointPatch, int j,
                              std::vector<int>& patches) const {
  visitPointBlockers(point, normal, pointPatch, j, [&](int k) {
    patches.push_back(k);
    return false;
  });
}

}  // namespace rt
