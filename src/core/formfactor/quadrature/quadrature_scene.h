// What the quadrature method finds out about a mesh once, before any pair: which patches occlude as whole
// convex polygons, the closed convex solids (blocks) among them, what each element reaches into, each
// element's measures for the a-priori order, and the blocks' shadow regions on the planes they stand on.
// Read by every thread (quadrature_pair.h).
#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include "core/formfactor/quadrature/block_shadow_regions.h"
#include "core/formfactor/quadrature/shadow_clipper.h"
#include "core/formfactor/quadrature/solid_silhouette.h"
#include "core/formfactor/quadrature/source_panels.h"
#include "core/formfactor/shaft_culling.h"
#include "core/mesh.h"

namespace rt {

struct QuadratureScene {
  QuadratureScene(const Mesh& mesh, const ShaftCulling& shafts);

  const Mesh& mesh;
  const ShaftCulling& shafts;
  // Occluders are whole patches where a patch is convex (its outline covers exactly its elements), the
  // elements otherwise.
  std::vector<bool> convex;                        // per patch
  std::vector<std::vector<int>> patchElements;     // per patch
  std::vector<std::vector<Vec3>> elementPolygons;  // per element of a patch that is not convex
  std::vector<SolidPlanes> solids;
  std::vector<int> solidOf;  // per patch: the solid it bounds, or -1
  std::vector<SolidShape> shapes;
  std::vector<Vec3> solidCentres;  // a point inside each solid, for the proofs by cross-sections
  // The solids each element reaches into (a floor element partly under a block): that part sees nothing,
  // and the jump at the block's edge is cut out of the source instead of left to the quadrature.
  std::vector<std::vector<int>> elementSolids;
  // Per element: wholly inside one of them (a floor element under a block standing on it). It sees nothing
  // and nothing sees it: every pair it is in is 0 before anything else is looked at.
  std::vector<char> enclosed;
  // Per element, what the a-priori order needs of it whole (most pairs clip neither element): its bound as
  // a receiver, and (with the bound's centre and radius) its longest edge as a source panel.
  struct Measure {
    ReceiverBound bound;
    double longest = 0;
    // Its one-point Gauss rule (node and weight), for far pairs taken at one point on each side, and its
    // corner count (3 or 4; 0, and no rule, for elements of more corners).
    Vec3 node = Vec3::Zero();
    double weight = 0;
    int corners = 0;
  };
  std::vector<Measure> measures;
  double regionEps = 0;  // a length: 1e-10 of the scene's size
  std::unique_ptr<ContactShadowRegions> contactRegions;

  // Whether no segment from element `source` to element `receiver` passes through both solids (proven as
  // shadow_overlap.h says): then what they hide of the pair is the sum of what each hides alone. The hull
  // tests it rests on are each of one element and two solids, made on first use and kept in a table of one
  // byte per element and ordered pair of solids; where that would exceed kMaxApartEntries, false (unproven:
  // such pairs take the adaptive rules, which need no proof) and apartTested() says so for the notes.
  bool shadowsApart(int source, int receiver, int a, int b) const;
  bool apartTested() const { return !outsideHull_.empty(); }
  static constexpr std::size_t kMaxApartEntries = std::size_t{1} << 24;

 private:
  // Whether solid `other` lies outside the convex hull of solid `near` and the element (kept).
  bool outsideHull(int element, int near, int other) const;
  // Per element and ordered pair of solids: 0 not yet known, 1 proven, 2 not. Threads that race to the same
  // entry prove the same answer.
  mutable std::vector<std::atomic<signed char>> outsideHull_;
};

// The receiver as the a-priori order sees it.
ReceiverBound boundOf(const ConvexPolygon& receiver, const Vec3& normal);

}  // namespace rt
