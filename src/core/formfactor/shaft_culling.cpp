#include "core/formfactor/shaft_culling.h"

#include <algorithm>

namespace rt {
namespace {

bool boxesOverlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double eps) {
  // Strict overlap: boxes that merely touch (a wall and the floor) do not count.
  return (a.min().array() < b.max().array() - eps).all() && (b.min().array() < a.max().array() - eps).all();
}

}  // namespace

ShaftCulling::ShaftCulling(const Mesh& mesh) {
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
  }

  // Side of every element with respect to every patch plane.
  elementSide_.assign(n * P, kOn);
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t k = 0; k < P; ++k) {
      if (patches_[k].box.isEmpty()) continue;
      std::uint8_t side = kOn;
      for (int v : mesh.elements[e].vertices) {
        const double d = patches_[k].normal.dot(mesh.vertices[v] - patches_[k].point);
        if (d > eps_) side |= kFront;
        if (d < -eps_) side |= kBack;
      }
      elementSide_[e * P + k] = side;
    }
  // Side of every patch (union of its elements) with respect to every patch plane.
  std::vector<std::uint8_t> patchSide(P * P, kOn);
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t k = 0; k < P; ++k) patchSide[elementPatch_[e] * P + k] |= elementSide_[e * P + k];

  blockers_.assign(P * P, {});
  for (std::size_t a = 0; a < P; ++a)
    for (std::size_t b = a + 1; b < P; ++b) {
      Eigen::AlignedBox3d shaft = patches_[a].box;
      shaft.extend(patches_[b].box);
      for (std::size_t k = 0; k < P; ++k) {
        if (k == a || k == b || patches_[k].box.isEmpty()) continue;
        if (!boxesOverlap(shaft, patches_[k].box, eps_)) continue;
        if (!(patchSide[k * P + a] & kFront) || !(patchSide[k * P + b] & kFront)) continue;
        const std::uint8_t sa = patchSide[a * P + k], sb = patchSide[b * P + k];
        const bool oneSide =
            ((sa | sb) & kBoth) != kBoth;  // never both strictly in front and strictly behind
        if (oneSide) continue;
        blockers_[a * P + b].push_back(static_cast<int>(k));
      }
      blockers_[b * P + a] = blockers_[a * P + b];
    }
}

bool ShaftCulling::mayBeOccluded(int i, int j) const {
  const std::size_t P = patchCount_;
  const int a = elementPatch_[i], b = elementPatch_[j];
  if (a == b) return false;  // one planar patch: its elements cannot see each other at all
  const auto& candidates = blockers_[a * P + b];
  if (candidates.empty()) return false;
  Eigen::AlignedBox3d shaft = elementBoxes_[i];
  shaft.extend(elementBoxes_[j]);
  for (int k : candidates) {
    if (!boxesOverlap(shaft, patches_[k].box, eps_)) continue;
    const std::uint8_t si = elementSide_[i * P + k], sj = elementSide_[j * P + k];
    if (((si | sj) & kBoth) != kBoth) continue;
    return true;
  }
  return false;
}

std::size_t ShaftCulling::occludablePatchPairs() const {
  std::size_t count = 0;
  for (std::size_t a = 0; a < patchCount_; ++a)
    for (std::size_t b = a + 1; b < patchCount_; ++b) count += blockers_[a * patchCount_ + b].empty() ? 0 : 1;
  return count;
}

}  // namespace rt
