// B per element as CSV, then where the element is: its centroid and unit normal, so that a value can be found
// by position without rebuilding the mesh (B stays in columns 4-6 for the readers written before). Written
// by `radiosity solve --output` and by the web edition's download, digit for digit alike (%.17g).
#pragma once

#include <string>

#include "core/mesh.h"
#include "core/scene.h"

namespace rt {

// element,patch,surface,area,B_r,B_g,B_b,x,y,z,nx,ny,nz
std::string radiosityCsv(const Scene& scene, const Mesh& mesh, const RgbField& B);

}  // namespace rt
