#include "core/raytrace/ray_tree.h"

namespace rt {

std::string toString(RayKind kind) {
  switch (kind) {
    case RayKind::Primary:
      return "primary";
    case RayKind::Shadow:
      return "shadow";
    case RayKind::Reflection:
      return "reflection";
  }
  return "?";
}

RayCounts RayTree::counts() const {
  RayCounts c;
  for (const RayNode& n : nodes) {
    if (n.kind == RayKind::Primary) ++c.primary;
    if (n.kind == RayKind::Shadow) ++c.shadow;
    if (n.kind == RayKind::Reflection) ++c.reflection;
  }
  return c;
}

}  // namespace rt
