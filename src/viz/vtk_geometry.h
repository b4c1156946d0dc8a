// Small VTK geometry builders shared by the 3D views (Nusselt, hemicube, rays): actors from plain points and
// polygons. Includes VTK: viz sources only.
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <vector>

#include "core/vec.h"

class vtkActor;
class vtkRenderer;
class vtkPolyData;

namespace rt::viz {

using Colour = std::array<double, 3>;

// A filled polygon (triangulated by VTK; convex or star-shaped from its first vertex).
vtkSmartPointer<vtkActor> polygonActor(const std::vector<Vec3>& points, const Colour& colour,
                                       double opacity = 1.0, bool lighting = false);
// Triangles (each three consecutive points).
vtkSmartPointer<vtkActor> trianglesActor(const std::vector<Vec3>& points, const Colour& colour,
                                         double opacity = 1.0);
// Line segments (each two consecutive points) drawn as lines of a pixel width.
vtkSmartPointer<vtkActor> linesActor(const std::vector<Vec3>& points, const Colour& colour, double width);
// A closed polyline.
vtkSmartPointer<vtkActor> loopActor(const std::vector<Vec3>& points, const Colour& colour, double width);
// Small spheres at points.
vtkSmartPointer<vtkActor> pointsActor(const std::vector<Vec3>& points, const Colour& colour, double radius);
// The unit hemisphere (or its wireframe) over `origin` around `normal`, with `u` as the first tangent axis.
vtkSmartPointer<vtkActor> hemisphereActor(const Vec3& origin, const Vec3& u, const Vec3& v,
                                          const Vec3& normal, double radius, const Colour& colour,
                                          double opacity, bool wireframe);
// Points the camera at the bounds of everything in the renderer from a direction, and fits the view.
void frameFromDirection(vtkRenderer* renderer, const Vec3& direction, const Vec3& up, double zoom = 1.0);

}  // namespace rt::viz
