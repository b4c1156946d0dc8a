// B per element as CSV, then where the element is: its centroid and unit normal, so that a value can be found
// by position without rebuilding the mesh (B stays in columns 4-6 for the readers written before). Written
// by `radiosity solve --output` and by the web edition's download, digit for digit alike (%.17g).
#pragma once

#include <string>

#include "core/basis/linear_basis.h"
#include "core/mesh.h"
#include "core/scene.h"

namespace rt {

// element,patch,surface,area,B_r,B_g,B_b,x,y,z,nx,ny,nz
std::string radiosityCsv(const Scene& scene, const Mesh& mesh, const RgbField& B);

// A linear basis's solution per node (`nodal`, one row per node of `basis`), with where the node is: its
// patch, the integral of its basis function (the node's share of area, with which power is counted), its
// position and its patch's unit normal. Throws std::invalid_argument when the sizes do not match.
// node,patch,surface,weight,B_r,B_g,B_b,x,y,z,nx,ny,nz
std::string nodalCsv(const Scene& scene, const Mesh& mesh, const LinearBasis& basis, const RgbField& nodal);

}  // namespace rt
