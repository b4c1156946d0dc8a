#include "core/io/ply_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "core/input_error.h"

namespace rt {
namespace {

int srgbByte(double v) {
  v = std::clamp(v, 0.0, 1.0);
  const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
  return static_cast<int>(std::lround(255 * s));
}

}  // namespace

RgbField flatCorners(const Mesh& mesh, const RgbField& B) {
  std::size_t count = 0;
  for (const Element& e : mesh.elements) count += e.vertices.size();
  RgbField out(static_cast<Eigen::Index>(count), 3);
  Eigen::Index row = 0;
  for (std::size_t i = 0; i < mesh.size(); ++i)
    for (std::size_t k = 0; k < mesh.elements[i].vertices.size(); ++k)
      out.row(row++) = B.row(static_cast<Eigen::Index>(i));
  return out;
}

void writeRadiosityPly(const Mesh& mesh, const RgbField& B, const RgbField& corners,
                       const std::string& path) {
  std::size_t cornerCount = 0;
  for (const Element& e : mesh.elements) cornerCount += e.vertices.size();
  if (static_cast<std::size_t>(B.rows()) != mesh.size() ||
      static_cast<std::size_t>(corners.rows()) != cornerCount)
    throw std::invalid_argument("writeRadiosityPly: B or the corner values do not match the mesh");
  // The brightest reflecting element is white: the light itself would leave the room black.
  double brightest = 0;
  for (Eigen::Index i = 0; i < B.rows(); ++i)
    if (!(mesh.emission.row(i).array() > 0).any()) brightest = std::max(brightest, B.row(i).maxCoeff());
  const double scale = brightest > 0 ? 1 / brightest : 1;
  std::ofstream out(path);
  if (!out) throw InputError({path}, "cannot write the PLY file");
  out << "ply\nformat ascii 1.0\ncomment radiosity B in W/m^2 per element (face) and per corner (vertex)\n"
      << "element vertex " << cornerCount << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property float B_r\nproperty float B_g\nproperty float B_b\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element face " << mesh.size() << "\n"
      << "property list uchar int vertex_indices\n"
      << "property float B_r\nproperty float B_g\nproperty float B_b\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "end_header\n";
  char line[512];
  Eigen::Index row = 0;
  for (const Element& e : mesh.elements)
    for (int v : e.vertices) {
      const Vec3& p = mesh.vertices[static_cast<std::size_t>(v)];
      std::snprintf(line, sizeof line, "%.9g %.9g %.9g %.7g %.7g %.7g %d %d %d\n", p.x(), p.y(), p.z(),
                    corners(row, 0), corners(row, 1), corners(row, 2), srgbByte(corners(row, 0) * scale),
                    srgbByte(corners(row, 1) * scale), srgbByte(corners(row, 2) * scale));
      out << line;
      ++row;
    }
  int first = 0;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const auto& vs = mesh.elements[i].vertices;
    out << vs.size();
    for (std::size_t k = 0; k < vs.size(); ++k) out << ' ' << first + static_cast<int>(k);
    first += static_cast<int>(vs.size());
    const auto r = static_cast<Eigen::Index>(i);
    std::snprintf(line, sizeof line, " %.7g %.7g %.7g %d %d %d\n", B(r, 0), B(r, 1), B(r, 2),
                  srgbByte(B(r, 0) * scale), srgbByte(B(r, 1) * scale), srgbByte(B(r, 2) * scale));
    out << line;
  }
  if (!out) throw InputError({path}, "error while writing the PLY file");
}

}  // namespace rt
