// What a closed convex block does to a pair, decided before the pair is prepared, from regions made once and
// reused for hundreds of pairs.
//
// Take an element e, a block strictly between e's corners and a plane P. A point y of P is hidden from some
// point of e exactly when y lies in the projection of the block from that point onto P, and from every
// point of e exactly when it lies in the projection from each of e's corners (for fixed y, the points of e's
// plane that y cannot see form a convex set: it holds all of e when it holds e's corners). So on P:
//  - the penumbra, the convex hull of the block's corners projected from e's corners, holds every point the
//    block shades from e: an element of P outside it sees all of e past the block;
//  - the umbra, the intersection of the block's projections from each of e's corners, holds exactly the
//    points the block hides all of e from: an element of P inside it sees nothing of e.
// Both depend on e, the block and P only. Along a row of the matrix (e fixed, the other element running)
// they are made once per plane (RowShadowRegions); where e lies in the plane a block stands on (the floor
// under the Cornell blocks), the block is not strictly between e and anything and the regions are made the
// other way round, once per element on that plane (ContactShadowRegions), and shared by all rows there.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/formfactor/quadrature/penumbra_region.h"
#include "core/formfactor/quadrature/solid_silhouette.h"
#include "core/vec.h"

namespace rt {

class BlockShadowRegion {
 public:
  // False (no regions) when some block corner is behind the plane (origin, unit normal) or not strictly
  // nearer to it than every corner of `from`.
  bool build(const SolidShape& block, const Vec3* from, int fromCount, const Vec3& origin, const Vec3& normal,
             double eps);
  // The polygon, lying in the plane, has no point the block shades from `from` (outside the penumbra by
  // more than eps).
  bool misses(const Vec3* polygon, int count) const { return !penumbra_.meets(polygon, count); }
  // Every corner of the polygon lies inside the umbra by more than eps: the block hides all of `from` from
  // all of it.
  bool hidesAll(const Vec3* polygon, int count) const;

 private:
  PenumbraRegion penumbra_;
  Vec3 origin_ = Vec3::Zero(), u_ = Vec3::Zero(), v_ = Vec3::Zero();
  double eps_ = 0;
  std::vector<Eigen::Vector2d> umbra_;  // counter-clockwise; empty when there is none
};

// Misses: no segment between the two meets the block; HidesAll: every one does; Shades: some may (the region
// says so); Unknown: no region (the block is not strictly between).
enum class BlockVerdict { Unknown, Misses, HidesAll, Shades };

// Per thread: the regions on each plane from the current row's element.
class RowShadowRegions {
 public:
  RowShadowRegions(const std::vector<SolidShape>& shapes, double eps) : shapes_(&shapes), eps_(eps) {}
  // What `solid` does between the row's element (`rowElement`, its corners) and the polygon `other` in the
  // plane (origin, unit normal).
  BlockVerdict judge(int rowElement, const Vec3* rowCorners, int rowCount, int solid, const Vec3* other,
                     int otherCount, const Vec3& origin, const Vec3& normal);

 private:
  struct Entry {
    int solid = -1;
    Vec3 normal = Vec3::Zero();
    double offset = 0;
    bool bounded = false;
    BlockShadowRegion region;
  };
  const std::vector<SolidShape>* shapes_;
  double eps_;
  int rowElement_ = -1;
  std::vector<Entry> entries_;
};

// For every block that stands on elements of the mesh (a face of it in their plane, facing them), the
// regions on that plane from every element: made once, read by all threads.
class ContactShadowRegions {
 public:
  // `polygon(e)` gives element e's corners; `normals` and `count` the elements'.
  ContactShadowRegions(const std::vector<SolidShape>& shapes, int elementCount,
                       const std::vector<std::vector<Vec3>>& polygons, const std::vector<Vec3>& normals,
                       double eps);
  // What `solid` does between `other` (element id) and `standing`, an element on the block's contact plane
  // (its polygon); Unknown when `standing` is not on it.
  BlockVerdict judge(int solid, int standingElement, const Vec3* standing, int standingCount,
                     int otherElement) const;
  bool any() const { return !contacts_.empty(); }

 private:
  struct Contact {
    int solid;
    std::vector<char> onPlane;               // per element: lies in the contact plane
    std::vector<BlockShadowRegion> regions;  // per element: from its corners onto the plane
    std::vector<char> bounded;
  };
  std::vector<Contact> contacts_;
  std::vector<int> contactOf_;  // per solid: index into contacts_, or -1
};

}  // namespace rt
