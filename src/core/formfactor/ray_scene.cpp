#include "core/formfactor/ray_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

#include "core/formfactor/ray_caster.h"

namespace rt {

bool RayFilter::accepts(unsigned primitive, float dx, float dy, float dz) const {
  const int element = (*primitiveElement)[primitive];
  if (element == ignoreA || element == ignoreB) return false;
  // A segment meets the plane of an end point's element only at that end point (a line crosses a plane
  // once), so a hit on another element of that plane is float rounding at the end: a ray grazing up a wall
  // would otherwise "hit" the wall's next element, which can happen far from the end at grazing angles.
  // A negative index is a free point (a query point not known to lie on an element): no plane to skip.
  const std::vector<int>& plane = *elementPlane;
  const int p = plane[static_cast<std::size_t>(element)];
  if ((ignoreA >= 0 && p == plane[static_cast<std::size_t>(ignoreA)]) ||
      (ignoreB >= 0 && p == plane[static_cast<std::size_t>(ignoreB)]))
    return false;
  if (frontOnlyNormals && (*frontOnlyNormals)[static_cast<std::size_t>(element)].dot(Vec3(dx, dy, dz)) >= 0)
    return false;
  return true;
}

bool rayBackendAvailable(RayBackend backend) {
  if (backend != RayBackend::embree) return true;
#if RT_HAVE_EMBREE
  return true;
#else
  return false;
#endif
}

struct RayScene::Impl {
  std::unique_ptr<RayCaster> caster;
  std::vector<int> primitiveElement;  // triangle -> element
  std::vector<Vec3> normals;          // per element
  std::vector<int> elementPlane;      // per element: elements in the same plane share the number
  float epsilon = 0;

  RayFilter filter(int ignoreA, int ignoreB) const {
    return {&primitiveElement, &elementPlane, nullptr, ignoreA, ignoreB};
  }
};

namespace {

FloatRay floatRay(const Vec3& origin, const Vec3& direction, float tnear, float tfar) {
  FloatRay ray{};
  for (int c = 0; c < 3; ++c) {
    ray.origin[c] = static_cast<float>(origin[c]);
    ray.direction[c] = static_cast<float>(direction[c]);
  }
  ray.tnear = tnear;
  ray.tfar = tfar;
  return ray;
}

}  // namespace

RayScene::RayScene(const Mesh& mesh, RayBackend backend) : impl_(std::make_unique<Impl>()) {
  if (!rayBackendAvailable(backend))
    throw std::invalid_argument("this build has no Embree: use the portable ray back end");
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  size_ = box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-300);
  // A few float ulps at the largest coordinate: enough to keep the end points' rounding (both back ends work
  // in float) from hitting their neighbours, and far below the 1e-6-of-the-scene gaps that must stay visible.
  double largest = 0;
  for (const Vec3& v : mesh.vertices) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  impl_->epsilon =
      static_cast<float>(4.0 * std::numeric_limits<float>::epsilon() * std::max(largest, 1e-3 * size_));
  std::vector<float> vertices;
  vertices.reserve(3 * mesh.vertices.size());
  for (const Vec3& v : mesh.vertices)
    for (int c = 0; c < 3; ++c) vertices.push_back(static_cast<float>(v[c]));
  std::vector<unsigned> triangles;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const auto& vs = mesh.elements[e].vertices;
    for (std::size_t k = 1; k + 1 < vs.size(); ++k) {
      triangles.insert(triangles.end(), {static_cast<unsigned>(vs[0]), static_cast<unsigned>(vs[k]),
                                         static_cast<unsigned>(vs[k + 1])});
      impl_->primitiveElement.push_back(static_cast<int>(e));
    }
    impl_->normals.push_back(mesh.elements[e].normal);
  }
  // Planes keyed by the unit normal and the offset relative to the scene size, rounded to 1e-9: coplanar
  // elements of different patches (a wall cut into strips, the two faces of a thin plate) get one number.
  std::map<std::array<long long, 4>, int> planes;
  auto key = [](double x) { return std::llround(x * 1e9); };
  for (const Element& e : mesh.elements) {
    Vec3 n = e.normal.normalized();
    // One sign per plane, so that the two faces of a two-sided wall (coincident, opposite normals) share it.
    const Eigen::Index largestAxis = [&n] {
      Eigen::Index k;
      n.cwiseAbs().maxCoeff(&k);
      return k;
    }();
    if (n(largestAxis) < 0) n = -n;
    const double offset = n.dot(mesh.vertices[e.vertices[0]]) / size_;
    const std::array<long long, 4> k{key(n.x()), key(n.y()), key(n.z()), key(offset)};
    impl_->elementPlane.push_back(planes.emplace(k, static_cast<int>(planes.size())).first->second);
  }
  if (backend != RayBackend::portable) impl_->caster = makeEmbreeCaster(vertices, triangles);
  backend_ = impl_->caster ? RayBackend::embree : RayBackend::portable;
  if (!impl_->caster) impl_->caster = makeBvhCaster(vertices, triangles);
}

RayScene::~RayScene() = default;

bool RayScene::visible(const Vec3& from, const Vec3& to, int ignoreA, int ignoreB) const {
  return unoccluded(from, to, impl_->epsilon, ignoreA, ignoreB);
}

bool RayScene::visibleAfter(const Vec3& from, const Vec3& to, double tnear, int ignoreTo) const {
  return unoccluded(from, to, static_cast<float>(std::max(tnear, 0.0)), -1, ignoreTo);
}

RayHit RayScene::firstHit(const Vec3& origin, const Vec3& direction, int ignore) const {
  return nearest(origin, direction, impl_->epsilon, ignore);
}

RayHit RayScene::firstHitAfter(const Vec3& origin, const Vec3& direction, double tnear) const {
  return nearest(origin, direction, static_cast<float>(std::max(tnear, 0.0)), -1);
}

bool RayScene::unoccluded(const Vec3& from, const Vec3& to, float tnear, int ignoreA, int ignoreB) const {
  const Vec3 d = to - from;
  const double length = d.norm();
  if (length == 0) return true;
  // Both ends' own elements are filtered out; the epsilons only keep float rounding at the end points from
  // registering grazing hits on their neighbours.
  const FloatRay ray = floatRay(from, d / length, tnear, static_cast<float>(length) - impl_->epsilon);
  if (!(ray.tfar > ray.tnear)) return true;
  return !impl_->caster->occluded(ray, impl_->filter(ignoreA, ignoreB));
}

RayHit RayScene::nearest(const Vec3& origin, const Vec3& direction, float tnear, int ignore) const {
  RayFilter filter = impl_->filter(ignore, ignore);
  auto intersect = [&](float from, float to) {
    RayHit hit;
    float t = 0;
    const int triangle = impl_->caster->nearest(floatRay(origin, direction, from, to), filter, t);
    if (triangle < 0) return hit;
    hit.element = impl_->primitiveElement[static_cast<std::size_t>(triangle)];
    hit.distance = t;
    hit.frontSide = impl_->normals[static_cast<std::size_t>(hit.element)].dot(direction) < 0;
    return hit;
  };
  const RayHit hit = intersect(tnear, std::numeric_limits<float>::infinity());
  if (hit.element < 0 || hit.frontSide) return hit;
  // A two-sided thin surface is often two coincident polygons back to back (as OBJ exporters write a
  // two-sided plane): both lie at the same distance, and which one the back end reports is arbitrary. The
  // light must land on the one that faces the ray, so a back-side hit looks again, at that distance only, for
  // a front side. The window is a few float ulps: a genuine gap of a thin plate is far wider.
  const float t = static_cast<float>(hit.distance);
  const float window = impl_->epsilon + 8 * std::numeric_limits<float>::epsilon() * t;
  filter.frontOnlyNormals = &impl_->normals;
  const RayHit front = intersect(std::max(tnear, t - window), t + window);
  return front.element >= 0 ? front : hit;
}

}  // namespace rt
