#include "core/io/radiosity_csv.h"

#include <cstdio>
#include <stdexcept>

namespace rt {

std::string radiosityCsv(const Scene& scene, const Mesh& mesh, const RgbField& B) {
  std::string out = "element,patch,surface,area,B_r,B_g,B_b,x,y,z,nx,ny,nz\n";
  char line[768];
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Element& e = mesh.elements[i];
    const auto r = static_cast<Eigen::Index>(i);
    std::snprintf(
        line, sizeof line, "%zu,%d,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", i,
        e.patch, scene.surfaces[scene.patches[e.patch].surface].name.c_str(), e.area, B(r, 0), B(r, 1),
        B(r, 2), e.centroid.x(), e.centroid.y(), e.centroid.z(), e.normal.x(), e.normal.y(), e.normal.z());
    out += line;
  }
  return out;
}

std::string nodalCsv(const Scene& scene, const Mesh& mesh, const LinearBasis& basis, const RgbField& nodal) {
  if (static_cast<std::size_t>(nodal.rows()) != basis.size())
    throw std::invalid_argument("nodalCsv: " + std::to_string(nodal.rows()) + " values for " +
                                std::to_string(basis.size()) + " nodes");
  // A patch's normal, from the first element of the patch.
  std::vector<Vec3> normals(scene.patches.size(), Vec3::Zero());
  for (const Element& e : mesh.elements)
    if (normals[std::size_t(e.patch)].isZero()) normals[std::size_t(e.patch)] = e.normal.normalized();
  std::string out = "node,patch,surface,weight,B_r,B_g,B_b,x,y,z,nx,ny,nz\n";
  char line[768];
  for (std::size_t k = 0; k < basis.size(); ++k) {
    const int patch = basis.nodePatch[k];
    const Vec3& p = mesh.vertices[std::size_t(basis.nodeVertex[k])];
    const Vec3& n = normals[std::size_t(patch)];
    const auto r = static_cast<Eigen::Index>(k);
    std::snprintf(line, sizeof line,
                  "%zu,%d,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", k, patch,
                  scene.surfaces[scene.patches[std::size_t(patch)].surface].name.c_str(), basis.weights(r),
                  nodal(r, 0), nodal(r, 1), nodal(r, 2), p.x(), p.y(), p.z(), n.x(), n.y(), n.z());
    out += line;
  }
  return out;
}

}  // namespace rt
