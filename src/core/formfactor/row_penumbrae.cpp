#include "core/formfactor/row_penumbrae.h"

#include <cmath>

namespace rt {

bool RowPenumbrae::rulesOut(int rowElement, const Vec3* rowCorners, int rowCount, int solid,
                            const Vec3* other, int otherCount, const Vec3& origin, const Vec3& normal) {
  if (solid < 0 || static_cast<std::size_t>(solid) >= shapes_->size()) return false;
  if (rowElement != rowElement_) {
    rowElement_ = rowElement;
    entries_.clear();
  }
  const double offset = normal.dot(origin);
  // The same plane to rounding: the elements of one wall share it up to the mesh's arithmetic.
  Entry* entry = nullptr;
  for (Entry& e : entries_)
    if (e.solid == solid && e.normal.dot(normal) > 1 - 1e-12 && std::abs(e.offset - offset) <= eps_) {
      entry = &e;
      break;
    }
  if (!entry) {
    entry = &entries_.emplace_back();
    entry->solid = solid;
    entry->normal = normal;
    entry->offset = offset;
    const SolidShape& shape = (*shapes_)[static_cast<std::size_t>(solid)];
    entry->bounded = entry->region.build(shape.corners.data(), static_cast<int>(shape.corners.size()),
                                         rowCorners, rowCount, origin, normal, eps_);
  }
  return entry->bounded && !entry->region.meets(other, otherCount);
}

}  // namespace rt
