// The scene of the visibility-event and hidden-form tests: a unit square source facing +z, a small diamond
// receiver above it facing -z (off the blocks' faces' planes, so that no event of one kind falls on the line
// of another and the tests can tell them apart), and two blocks between them.
#pragma once

#include "core/box_solid.h"
#include "core/formfactor/quadrature/source_panels.h"

namespace rt::event_scenes {

inline const ConvexPolygon kSource = polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});  // faces +z
inline const SourcePanel kPanel{kSource.v[0], kSource.v[1], kSource.v[2], kSource.v[3]};
inline const Vec3 kUp{0, 0, 1}, kDown{0, 0, -1};
inline const ConvexPolygon kReceiver =
    polygon({{0.47, 0.37, 3}, {0.32, 0.52, 3}, {0.47, 0.67, 3}, {0.62, 0.52, 3}});  // faces -z
// A slab whose edge sweeps across the receiver as x crosses the source (from one side nothing of the receiver
// is hidden, from the other all of it), and a block whose corner's shadow crosses it as well; the planes of
// both one's side faces cut the source (the silhouette changes there).
inline const Box kSlab = box({0.5, -1, 1.4}, {1.5, 2, 1.6});
inline const Box kCorner = box({0.5, 0.5, 1.4}, {1.5, 1.5, 1.6});

}  // namespace rt::event_scenes
