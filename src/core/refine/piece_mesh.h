// Turning sets of polygon pieces into an rt::Mesh, and the bookkeeping of meshes whose elements were split
// independently: hanging (T-) vertices, same-surface neighbours, a crack-free fan version for display.
#pragma once

#include <vector>

#include "core/mesh.h"
#include "core/refine/refine.h"

namespace rt {

// One element per piece (3 or 4 vertices, counter-clockwise from the front), welded vertices, materials from
// the scene. patchOfPiece[k] is the scene patch piece k lies on.
Mesh meshFromPieces(const Scene& scene, const std::vector<Polygon>& pieces,
                    const std::vector<int>& patchOfPiece);

// Every vertex lying strictly inside an edge of an element of the same patch.
std::vector<TVertex> findTVertices(const Mesh& mesh);

// Elements touching element e (sharing a vertex, or a hanging vertex on one of its edges) on the same surface
// and facing the same way: the neighbours whose radiosity should vary smoothly into e's.
std::vector<std::vector<int>> smoothNeighbours(const Scene& scene, const Mesh& mesh,
                                               const std::vector<TVertex>& tVertices);

// Splits a triangle or quad into 4 (edge midpoints; quads also at the centre).
std::vector<Polygon> splitInFour(const Polygon& polygon);

}  // namespace rt
