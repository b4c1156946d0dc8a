// The solved mesh as a PLY file that ParaView and Blender open: every element a face carrying its radiosity
// (face properties B_r, B_g, B_b and a display colour), every element corner a vertex of its own carrying the
// per-vertex radiosity given for it (so that values stay discontinuous where the solution is: creases,
// material edges) and a display colour, which Blender imports as the vertex colour layer. ASCII, one file.
#pragma once

#include <string>

#include "core/mesh.h"

namespace rt {

// `corners` holds one RGB row per element corner, element by element in the order of Element::vertices (a
// smooth interpolation, or each element's own B for flat corners). Display colours: B divided by the largest
// B of a non-emitting element, clamped, sRGB-encoded. Throws InputError naming the path when it cannot be
// written, std::invalid_argument when the sizes do not match the mesh.
void writeRadiosityPly(const Mesh& mesh, const RgbField& B, const RgbField& corners, const std::string& path);

// Each corner carrying its element's B (the flat corners of writeRadiosityPly).
RgbField flatCorners(const Mesh& mesh, const RgbField& B);

}  // namespace rt
