// Which patches bound closed convex solids (a block with its bottom, given as separate faces)? Their back
// faces need no clipping from outside (shadow_clipper.h), which halves the occluders of a block.
#pragma once

#include <cmath>
#include <tuple>
#include <vector>

#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/vec.h"

namespace rt {

// Corners that agree to 1e-9 of the outlines' size are the same corner: this gives each its key, as every
// function here and solidShapes() have it.
class CornerKey {
 public:
  using Key = std::tuple<long long, long long, long long>;
  explicit CornerKey(const std::vector<const std::vector<Vec3>*>& outlines);
  double size() const { return size_; }  // the largest coordinate; 0 when there is nothing
  Key operator()(const Vec3& v) const {
    return Key{std::llround(v.x() / quantum_), std::llround(v.y() / quantum_),
               std::llround(v.z() / quantum_)};
  }

 private:
  double size_ = 0, quantum_ = 1;
};

// outlines[k]: patch k's convex outline, counter-clockwise seen from its front. Returns per patch the index
// of the solid it bounds, or -1, and fills `planes` with each solid's outward face planes. A group of
// patches joined by shared edges is a solid when every edge is shared by exactly two of its faces, in
// opposite directions (closed and consistently oriented), and every vertex lies on or behind every face
// (convex, facing outwards). A room's inward-facing walls are closed too, but not outward: they are no solid.
std::vector<int> closedConvexSolids(const std::vector<const std::vector<Vec3>*>& outlines,
                                    std::vector<SolidPlanes>& planes);

// For each group of patches joined by shared edges whose unshared edges form one planar loop (a block given
// without its bottom, as the Cornell box's are), that loop reversed: the face that would close it, to be
// passed to closedConvexSolids() and solidShapes() after the patches (never an occluder itself). Segments
// see a convex solid missing one face as the closed one: one that enters through the missing face leaves
// through another (not through the same plane), which blocks it, one-sided polygons being opaque from
// behind; and a point under the missing face (the floor under such a block) sees only the faces' backs.
std::vector<std::vector<Vec3>> closingFaces(const std::vector<const std::vector<Vec3>*>& outlines);

// The area of the part of a convex polygon inside the solid (on or behind every face plane, within eps).
// A floor element partly under a block: that part sees nothing at all.
double areaInside(const ConvexPolygon& polygon, const SolidPlanes& solid, double eps);

// Appends to `out` the convex pieces of `polygon` outside the solid (in front of some face plane).
void piecesOutside(const ConvexPolygon& polygon, const SolidPlanes& solid, double eps,
                   std::vector<ConvexPolygon>& out);

}  // namespace rt
