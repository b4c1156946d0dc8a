#include "core/io/radiosity_csv.h"

#include <cstdio>

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

}  // namespace rt
