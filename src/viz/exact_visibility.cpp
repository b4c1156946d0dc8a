#include "viz/exact_visibility.h"

#include <cmath>
#include <stdexcept>

#ifdef RT_HAVE_EXACT
#include "exact/exact_reference.h"
#endif

namespace rt::viz {

bool exactVisibilityAvailable() {
#ifdef RT_HAVE_EXACT
  return true;
#else
  return false;
#endif
}

VisibilityRegions exactVisibilityRegions(const Mesh& mesh, int source, int receiver) {
#ifdef RT_HAVE_EXACT
  const exact::VisibleRegion region =
      exact::visibleRegion(mesh, source, mesh.elements[source].centroid, receiver);
  VisibilityRegions regions;
  regions.source = source;
  regions.receiver = receiver;
  regions.point = region.point;
  regions.receiverOutline = region.clippedReceiver;
  regions.shadows = region.occluderProjections;
  regions.shadowOwners = region.projectionOwners;
  for (const exact::PolygonWithHoles& p : region.visible) regions.visible.emplace_back(p.outer, p.holes);
  regions.formFactor = region.formFactor;
  regions.unoccludedFormFactor = region.unoccludedFormFactor;
  return regions;
#else
  (void)mesh;
  (void)source;
  (void)receiver;
  throw std::runtime_error(
      "the visibility view needs the exact reference (configure with RT_BUILD_EXACT=ON)");
#endif
}

int halfBlockedViewer(const Mesh& mesh, int receiver, int fallback) {
#ifdef RT_HAVE_EXACT
  double best = 2;
  int chosen = fallback;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    if (static_cast<int>(e) == receiver) continue;
    const exact::VisibleRegion region =
        exact::visibleRegion(mesh, static_cast<int>(e), mesh.elements[e].centroid, receiver);
    if (!region.facing || region.unoccludedFormFactor <= 0) continue;
    const double blocked = std::abs(region.formFactor / region.unoccludedFormFactor - 0.5);
    if (blocked < best) {
      best = blocked;
      chosen = static_cast<int>(e);
    }
  }
  return chosen;
#else
  (void)mesh;
  (void)receiver;
  return fallback;
#endif
}

}  // namespace rt::viz
