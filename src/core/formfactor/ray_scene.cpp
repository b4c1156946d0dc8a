#include "core/formfactor/ray_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

namespace rt {
namespace {

// The context Embree hands to the filter: which two elements the current ray must pass through.
struct IgnoringContext {
  RTCIntersectContext base;
  const std::vector<int>* primitiveElement;
  const std::vector<int>* elementPlane;
  const std::vector<Vec3>*
      frontOnlyNormals;  // non-null: pass through every element the ray meets from behind
  int ignoreA, ignoreB;
};

void ignoreOwnElements(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const IgnoringContext*>(args->context);
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] == 0) continue;
    const unsigned primitive = RTCHitN_primID(args->hit, args->N, k);
    const int element = (*context->primitiveElement)[primitive];
    if (element == context->ignoreA || element == context->ignoreB) {
      args->valid[k] = 0;
      continue;
    }
    // A segment meets the plane of an end point's element only at that end point (a line crosses a plane
    // once), so a hit on another element of that plane is float rounding at the end: a ray grazing up a wall
    // would otherwise "hit" the wall's next element, which can happen far from the end at grazing angles.
    // A negative index is a free point (a query point not known to lie on an element): no plane to skip.
    const std::vector<int>& plane = *context->elementPlane;
    const int p = plane[static_cast<std::size_t>(element)];
    if ((context->ignoreA >= 0 && p == plane[static_cast<std::size_t>(context->ignoreA)]) ||
        (context->ignoreB >= 0 && p == plane[static_cast<std::size_t>(context->ignoreB)]))
      args->valid[k] = 0;
    else if (context->frontOnlyNormals) {
      const Vec3 d(RTCRayN_dir_x(args->ray, args->N, k), RTCRayN_dir_y(args->ray, args->N, k),
                   RTCRayN_dir_z(args->ray, args->N, k));
      if ((*context->frontOnlyNormals)[static_cast<std::size_t>(element)].dot(d) >= 0) args->valid[k] = 0;
    }
  }
}

}  // namespace

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<int> primitiveElement;  // triangle -> element
  std::vector<Vec3> normals;          // per element
  std::vector<int> elementPlane;      // per element: elements in the same plane share the number
  float epsilon = 0;
};

RayScene::RayScene(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  size_ = box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-300);
  // A few float ulps at the largest coordinate: enough to keep the end points' rounding (Embree works in
  // float) from hitting their neighbours, and far below the 1e-6-of-the-scene gaps that must stay visible.
  double largest = 0;
  for (const Vec3& v : mesh.vertices) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  impl_->epsilon =
      static_cast<float>(4.0 * std::numeric_limits<float>::epsilon() * std::max(largest, 1e-3 * size_));
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw std::runtime_error("Embree: cannot create a device");
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) vertices[3 * v + c] = static_cast<float>(mesh.vertices[v][c]);
  std::size_t triangles = 0;
  for (const Element& e : mesh.elements) triangles += e.vertices.size() - 2;
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles));
  impl_->primitiveElement.reserve(triangles);
  std::size_t t = 0;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const auto& vs = mesh.elements[e].vertices;
    for (std::size_t k = 1; k + 1 < vs.size(); ++k, ++t) {
      indices[3 * t] = static_cast<unsigned>(vs[0]);
      indices[3 * t + 1] = static_cast<unsigned>(vs[k]);
      indices[3 * t + 2] = static_cast<unsigned>(vs[k + 1]);
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
    const Eigen::Index largest = [&n] {
      Eigen::Index k;
      n.cwiseAbs().maxCoeff(&k);
      return k;
    }();
    if (n(largest) < 0) n = -n;
    const double offset = n.dot(mesh.vertices[e.vertices[0]]) / size_;
    const std::array<long long, 4> k{key(n.x()), key(n.y()), key(n.z()), key(offset)};
    impl_->elementPlane.push_back(planes.emplace(k, static_cast<int>(planes.size())).first->second);
  }
  rtcSetGeometryIntersectFilterFunction(geometry, ignoreOwnElements);
  rtcSetGeometryOccludedFilterFunction(geometry, ignoreOwnElements);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(impl_->scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(impl_->scene);
}

RayScene::~RayScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

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
  IgnoringContext context;
  rtcInitIntersectContext(&context.base);
  context.primitiveElement = &impl_->primitiveElement;
  context.elementPlane = &impl_->elementPlane;
  context.frontOnlyNormals = nullptr;
  context.ignoreA = ignoreA;
  context.ignoreB = ignoreB;
  RTCRay ray{};
  ray.org_x = static_cast<float>(from.x());
  ray.org_y = static_cast<float>(from.y());
  ray.org_z = static_cast<float>(from.z());
  ray.dir_x = static_cast<float>(d.x() / length);
  ray.dir_y = static_cast<float>(d.y() / length);
  ray.dir_z = static_cast<float>(d.z() / length);
  // Both ends' own elements are filtered out; the epsilons only keep float rounding at the end points from
  // registering grazing hits on their neighbours.
  ray.tnear = tnear;
  ray.tfar = static_cast<float>(length) - impl_->epsilon;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  if (!(ray.tfar > ray.tnear)) return true;
  rtcOccluded1(impl_->scene, &context.base, &ray);
  return ray.tfar >= 0;  // Embree sets tfar to -inf on a hit
}

RayHit RayScene::nearest(const Vec3& origin, const Vec3& direction, float tnear, int ignore) const {
  IgnoringContext context;
  rtcInitIntersectContext(&context.base);
  context.primitiveElement = &impl_->primitiveElement;
  context.elementPlane = &impl_->elementPlane;
  context.frontOnlyNormals = nullptr;
  context.ignoreA = ignore;
  context.ignoreB = ignore;
  auto intersect = [&](float tnear, float tfar) {
    RTCRayHit query{};
    query.ray.org_x = static_cast<float>(origin.x());
    query.ray.org_y = static_cast<float>(origin.y());
    query.ray.org_z = static_cast<float>(origin.z());
    query.ray.dir_x = static_cast<float>(direction.x());
    query.ray.dir_y = static_cast<float>(direction.y());
    query.ray.dir_z = static_cast<float>(direction.z());
    query.ray.tnear = tnear;
    query.ray.tfar = tfar;
    query.ray.mask = 0xFFFFFFFFu;
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context.base, &query);
    RayHit hit;
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.element = impl_->primitiveElement[query.hit.primID];
    hit.distance = query.ray.tfar;
    hit.frontSide = impl_->normals[static_cast<std::size_t>(hit.element)].dot(direction) < 0;
    return hit;
  };
  const RayHit hit = intersect(tnear, std::numeric_limits<float>::infinity());
  if (hit.element < 0 || hit.frontSide) return hit;
  // A two-sided thin surface is often two coincident polygons back to back (as OBJ exporters write a
  // two-sided plane): both lie at the same distance, and which one Embree reports is arbitrary. The light
  // must land on the one that faces the ray, so a back-side hit looks again, at that distance only, for a
  // front side. The window is a few float ulps: a genuine gap of a thin plate is far wider.
  const float t = static_cast<float>(hit.distance);
  const float window = impl_->epsilon + 8 * std::numeric_limits<float>::epsilon() * t;
  context.frontOnlyNormals = &impl_->normals;
  const RayHit front = intersect(std::max(tnear, t - window), t + window);
  return front.element >= 0 ? front : hit;
}

}  // namespace rt
