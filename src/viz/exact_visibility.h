// The visible part of a receiver as seen from a point of a source element, computed by the exact reference
// (rt_exact's clipped projections of the occluders), ready for the visibility view. One meaning of the
// `visibility` view for the lessons and `radiosity figure --view visibility`.
#pragma once

#include "core/mesh.h"
#include "viz/visibility_view.h"

namespace rt::viz {

// False when this build has no exact reference (the visibility view then cannot be drawn).
bool exactVisibilityAvailable();
// From the centroid of `source` towards `receiver`. Throws std::runtime_error without the exact reference.
VisibilityRegions exactVisibilityRegions(const Mesh& mesh, int source, int receiver);
// The element whose view of `receiver` is closest to half blocked, the telling example; `fallback` when no
// element sees it partly.
int halfBlockedViewer(const Mesh& mesh, int receiver, int fallback);

}  // namespace rt::viz
