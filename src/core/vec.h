// Small vocabulary types shared by every layer: 3D points/vectors and RGB triples (Eigen).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace rt {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;
// Per-channel quantities (reflectance, emission, radiosity) are arrays so that products are component-wise.
using Rgb = Eigen::Array3d;
// One RGB value per element: row i is element i, columns are r, g, b.
using RgbField = Eigen::Matrix<double, Eigen::Dynamic, 3>;
// A planar convex polygon, counter-clockwise seen from the side it faces.
using Polygon = std::vector<Vec3>;

}  // namespace rt
